import { useFigure, type FigureStatus } from "../figure";

const NOTES: Partial<Record<FigureStatus, string>> = {
  waiting: "The character appears when the motion is done.",
  loading: "Loading the character…",
};

/** The view's figure: the part-coloured mannequin or the skinned character (remembered). While
 * a motion streams the mannequin stands in, and this says when the character comes. */
export function FigureToggle() {
  const figure = useFigure((s) => s.figure);
  const status = useFigure((s) => s.status);
  const error = useFigure((s) => s.error);
  const setFigure = useFigure((s) => s.setFigure);
  const on = figure === "character";
  const note = status === "error" ? `Showing the mannequin: ${error}.` : NOTES[status];
  return (
    <>
      <button
        data-testid="figure-character"
        aria-pressed={on}
        className={on ? "active" : ""}
        title="Show the people as the skinned character (the GLB export's mesh) instead of the mannequin"
        onClick={() => setFigure(on ? "mannequin" : "character")}
      >
        ◉ Character
      </button>
      {on && note && (
        <span className="tools__hint small" data-testid="figure-note" role="status">
          {note}
        </span>
      )}
    </>
  );
}
