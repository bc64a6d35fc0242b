import { useEffect, useState, type FormEvent } from "react";
import { useShallow } from "zustand/react/shallow";
import { promptLength } from "../api/formCheck";
import { generate, generateBlocked } from "../studio";
import { useStudio, type Persons } from "../store";
import { currentProblems, useFormTried } from "./FormProblems";
import { PathChip } from "./PathPanel";
import { SeedField } from "./SeedField";

const EXAMPLES = ["a person walks forward", "two people dance salsa", "a person jumps twice"];

/** Prompt, number of people, duration and the Generate button. The form keeps to the API's
 * limits (api/limits.ts, from its schema): a counter in the prompt, seconds in range, an empty
 * prompt never sent; its problems are said under the header (FormProblems), and editing it
 * clears an error banner left from before. */
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
  // the seconds field's text as typed ("" or "-" while typing); the store holds its number
  const [secondsText, setSecondsText] = useState(String(seconds));
  useEffect(() => {
    setSecondsText((t) => (Number(t) === seconds && t.trim() !== "" ? t : Number.isFinite(seconds) ? String(seconds) : t));
  }, [seconds]);

  /** An edit of the form: an old error banner no longer applies, nor a stopped Generate. */
  const edited = () => {
    if (useStudio.getState().error) useStudio.getState().setError(null);
    if (useFormTried.getState().tried) useFormTried.setState({ tried: false });
  };

  const submit = (e: FormEvent) => {
    e.preventDefault();
    if (currentProblems().length) {
      useFormTried.setState({ tried: true }); // said under the header; nothing is sent
      return;
    }
    if (!blocked) void generate();
  };

  const length = promptLength(prompt);
  const over = length > limits.promptMax;
  const secondsBad = !Number.isFinite(seconds) || seconds < limits.secondsMin || seconds > limits.secondsMax;

  return (
    <form className="prompt-bar" onSubmit={submit} aria-label="Generate a motion" noValidate>
      <span className="prompt-field">
        <input
          className="prompt-bar__input"
          data-testid="prompt"
          aria-label="Prompt"
          aria-invalid={over || undefined}
          aria-describedby="prompt-count"
          placeholder={`Describe a motion, e.g. “${EXAMPLES[(persons - 1) % EXAMPLES.length]}”`}
          value={prompt}
          onChange={(e) => {
            edited();
            setPrompt(e.target.value);
          }}
        />
        <span
          id="prompt-count"
          className={`prompt-count${over ? " prompt-count--over" : ""}`}
          data-testid="prompt-count"
          data-max={limits.promptMax}
          aria-live={over ? "polite" : "off"}
          title={`At most ${limits.promptMax} characters`}
        >
          {length.toLocaleString("en")} / {limits.promptMax}
        </span>
      </span>
      <div className="segmented" role="group" aria-label="Persons">
        {Array.from({ length: limits.personsMax }, (_, i) => (i + 1) as Persons).map((n) => (
          <button
            key={n}
            type="button"
            data-testid={`persons-${n}`}
            aria-pressed={persons === n}
            className={persons === n ? "active" : ""}
            onClick={() => {
              edited();
              setPersons(n);
            }}
            title={n === 1 ? "One person" : n === 2 ? "Two people" : `${n} people`}
          >
            {n === 1 ? "1 person" : `${n} people`}
          </button>
        ))}
      </div>
      <label className="seconds">
        <input
          type="number"
          data-testid="seconds"
          aria-label="Seconds"
          aria-invalid={secondsBad || undefined}
          min={limits.secondsMin}
          max={limits.secondsMax}
          step={1}
          value={secondsText}
          onChange={(e) => {
            edited();
            setSecondsText(e.target.value);
            setSeconds(e.target.value.trim() === "" ? NaN : Number(e.target.value));
          }}
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
