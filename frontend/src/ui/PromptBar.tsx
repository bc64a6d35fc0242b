import type { FormEvent } from "react";
import { useShallow } from "zustand/react/shallow";
import { generate, generateBlocked } from "../studio";
import { useStudio, type Persons } from "../store";
import { PathChip } from "./PathPanel";
import { SeedField } from "./SeedField";

const EXAMPLES = ["a person walks forward", "two people dance salsa", "a person jumps twice"];

/** Prompt, number of people, duration and the Generate button. */
export function PromptBar() {
  const { prompt, persons, seconds, setPrompt, setPersons, setSeconds } = useStudio(
    useShallow((s) => ({
      prompt: s.prompt,
      persons: s.persons,
      seconds: s.seconds,
      setPrompt: s.setPrompt,
      setPersons: s.setPersons,
      setSeconds: s.setSeconds,
    })),
  );
  const phase = useStudio((s) => s.stream.phase);
  const limits = useStudio((s) => s.limits); // from the API's schema (api/limits.ts)
  const busy = phase === "connecting" || phase === "generating";
  // one job per intent: disabled while this very request starts or runs; a changed one may go
  // (it replaces the running job)
  const blocked = useStudio(generateBlocked);

  const submit = (e: FormEvent) => {
    e.preventDefault();
    if (!blocked) void generate();
  };

  return (
    <form className="prompt-bar" onSubmit={submit} aria-label="Generate a motion" noValidate>
      <input
        className="prompt-bar__input"
        data-testid="prompt"
        aria-label="Prompt"
        placeholder={`Describe a motion, e.g. “${EXAMPLES[(persons - 1) % EXAMPLES.length]}”`}
        value={prompt}
        maxLength={limits.promptMax}
        onChange={(e) => setPrompt(e.target.value)}
      />
      <div className="segmented" role="group" aria-label="Persons">
        {([1, 2] as Persons[]).map((n) => (
          <button
            key={n}
            type="button"
            data-testid={`persons-${n}`}
            aria-pressed={persons === n}
            className={persons === n ? "active" : ""}
            onClick={() => setPersons(n)}
            title={n === 1 ? "One person" : "Two people"}
          >
            {n === 1 ? "1 person" : "2 people"}
          </button>
        ))}
      </div>
      <label className="seconds">
        <input
          type="number"
          data-testid="seconds"
          aria-label="Seconds"
          min={limits.secondsMin}
          max={limits.secondsMax}
          step={1}
          value={seconds}
          onChange={(e) => setSeconds(Number(e.target.value))}
        />
        <span>s</span>
      </label>
      <SeedField />
      <PathChip />
      <button
        className="primary"
        type="submit"
        data-testid="generate"
        disabled={blocked}
        title={busy && !blocked ? "Generate this instead (the running generation is cancelled)" : undefined}
      >
        {blocked ? "Generating…" : "Generate"}
      </button>
    </form>
  );
}
