import { useState, type FormEvent } from "react";
import { personName } from "./format";
import { useShallow } from "zustand/react/shallow";
import { applyPartEdit } from "../directing/actions";
import { PART_LABELS } from "../directing/parts";
import { FPS, useStudio } from "../store";

const SUGGESTIONS = ["wave", "raise above head", "kick forward", "crouch"];
// The head's own words (the head primitive: look, nod, shake).
const HEAD_SUGGESTIONS = ["look up", "nod twice", "shake your head", "look left"];

/** The editor for the clicked body part: an instruction, optionally over the timeline's range. */
export function PartEditor() {
  const s = useStudio(
    useShallow((s) => ({
      selected: s.selected,
      range: s.range,
      editing: s.editing,
      persons: s.motionPersons,
      ready: s.stream.phase === "done" && Boolean(s.motionId),
      select: s.select,
      setRange: s.setRange,
    })),
  );
  const [text, setText] = useState("");
  if (!s.selected) return null;
  const two = s.persons > 1;
  const hints = s.selected.part === "head" ? HEAD_SUGGESTIONS : SUGGESTIONS;
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    if (text.trim() && (await applyPartEdit(text.trim()))) setText("");
  };
  return (
    <form className="part-editor" data-testid="part-editor" onSubmit={submit} aria-label="Edit a body part">
      <div className="part-editor__head">
        <strong data-testid="selected-part">
          {PART_LABELS[s.selected.part]}
          {two ? ` · ${personName(s.selected.person)}` : ""}
        </strong>
        <button type="button" className="icon-button" aria-label="Close" onClick={() => s.select(null)}>
          ×
        </button>
      </div>
      <input
        data-testid="part-prompt"
        aria-label="Instruction"
        placeholder={`e.g. “${hints[0]}”, “${hints[1]}”`}
        value={text}
        onChange={(e) => setText(e.target.value)}
        list="part-suggestions"
      />
      <datalist id="part-suggestions">
        {hints.map((x) => (
          <option key={x} value={x} />
        ))}
      </datalist>
      <p className="muted small" data-testid="part-range">
        {s.range
          ? `Frames ${s.range[0]}–${s.range[1]} (${(s.range[0] / FPS).toFixed(2)}–${(s.range[1] / FPS).toFixed(2)} s)`
          : "Whole clip — drag on the timeline to limit the edit."}
        {s.range && (
          <button type="button" className="link" onClick={() => s.setRange(null)}>
            clear
          </button>
        )}
      </p>
      {two && <p className="small warn">Edits work on one-person motions.</p>}
      <button className="primary" type="submit" data-testid="part-apply" disabled={!text.trim() || s.editing || !s.ready || two}>
        {s.editing ? "Applying…" : "Apply edit"}
      </button>
    </form>
  );
}
