import { useState, type FormEvent } from "react";
import { useShallow } from "zustand/react/shallow";
import { canReact, MAX_INTENT } from "../directing/react";
import { react } from "../studio";
import { useStudio } from "../store";

const INTENTS = ["shake hands", "dance with them", "hug", "push them away", "follow them"];

/** "Person 2 reacts to Person 1": add a second person who reacts, frame by frame, to the one-person motion on
 * stage (an optional intent steers them). Shown for a finished one-person motion only. */
export function ReactorPanel() {
  const s = useStudio(
    useShallow((s) => ({
      can: canReact(s),
      streaming: s.stream.mode === "react" && (s.stream.phase === "connecting" || s.stream.phase === "generating"),
    })),
  );
  const [intent, setIntent] = useState("");
  if (!s.can && !s.streaming) return null;
  const submit = (e: FormEvent) => {
    e.preventDefault();
    if (s.can) void react(intent);
  };
  return (
    <section className="panel" aria-labelledby="reactor-title" data-testid="reactor">
      <h2 id="reactor-title">Person 2 reacts</h2>
      <form className="reactor" onSubmit={submit}>
        <p className="muted small">
          Add Person 2, who reacts to Person 1, generated frame by frame as Person 1 moves.
        </p>
        <input
          data-testid="reactor-intent"
          aria-label="Intent (optional)"
          placeholder="Intent (optional): shake hands…"
          maxLength={MAX_INTENT}
          value={intent}
          onChange={(e) => setIntent(e.target.value)}
          list="reactor-intents"
          disabled={s.streaming}
        />
        <datalist id="reactor-intents">
          {INTENTS.map((x) => (
            <option key={x} value={x} />
          ))}
        </datalist>
        <button className="primary" type="submit" data-testid="reactor-add" disabled={!s.can}>
          {s.streaming ? "Reacting…" : "Add a reactor"}
        </button>
      </form>
    </section>
  );
}
