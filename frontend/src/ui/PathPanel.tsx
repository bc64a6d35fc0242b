import { useShallow } from "zustand/react/shallow";
import { applyPathToMotion } from "../directing/actions";
import { PRESETS, pathLength, presetPoints, type Preset } from "../directing/path";
import { useStudio } from "../store";
import { personName } from "./format";

const PRESET_LABELS: Record<Preset, string> = { circle: "◯ Circle", zigzag: "Zigzag", s: "S", heart: "♡ Heart" };

/** The path a person follows: presets, size, Person 1 / 2, clear, apply to the current motion. */
export function PathPanel() {
  const s = useStudio(
    useShallow((s) => ({
      path: s.path,
      tool: s.tool,
      setPath: s.setPath,
      persons: s.persons,
      ready: s.stream.phase === "done" && Boolean(s.motionId),
      editing: s.editing,
    })),
  );
  const { path } = s;
  if (s.tool !== "path" && path.points.length < 2) return null;
  const drop = (preset: Preset, size = path.size) => s.setPath({ points: presetPoints(preset, size), preset, size });

  return (
    <section className="panel" aria-labelledby="path-title" data-testid="path-panel">
      <h2 id="path-title">Path</h2>
      <div className="button-row">
        <div className="segmented" role="group" aria-label="Who follows the path">
          {([0, 1] as const).map((p) => (
            <button
              key={p}
              data-testid={`path-person-${p}`}
              className={path.person === p ? "active" : ""}
              aria-pressed={path.person === p}
              disabled={p === 1 && s.persons < 2}
              onClick={() => s.setPath({ person: p })}
            >
              {personName(p)}
            </button>
          ))}
        </div>
      </div>
      <div className="button-row path__presets">
        {PRESETS.map((p) => (
          <button key={p} data-testid={`preset-${p}`} className={path.preset === p ? "active" : ""} onClick={() => drop(p)}>
            {PRESET_LABELS[p]}
          </button>
        ))}
      </div>
      <label className="path__size">
        Size
        <input
          type="number"
          data-testid="path-size"
          min={0.5}
          max={10}
          step={0.5}
          value={path.size}
          onChange={(e) => {
            const size = Math.max(0.5, Math.min(10, Number(e.target.value) || 0.5));
            if (path.preset) drop(path.preset, size);
            else s.setPath({ size });
          }}
        />
        m
      </label>
      <p className="muted small" data-testid="path-summary">
        {path.points.length >= 2
          ? `${path.points.length} points · ${pathLength(path.points).toFixed(1)} m · ${personName(path.person)} follows it in the next Generate`
          : "Drag on the floor to draw, or pick a preset."}
      </p>
      <div className="button-row">
        <button data-testid="path-clear" disabled={!path.points.length} onClick={() => s.setPath({ points: [], preset: null })}>
          Clear
        </button>
        <button
          data-testid="path-apply"
          disabled={path.points.length < 2 || !s.ready || s.editing}
          onClick={() => void applyPathToMotion()}
        >
          Apply to current motion
        </button>
      </div>
    </section>
  );
}

/** Beside Generate while a path is set: it applies to the next Generate only (then it is
 * used up), with a button to remove it first. */
export function PathChip() {
  const path = useStudio((s) => s.path);
  const setPath = useStudio((s) => s.setPath);
  const persons = useStudio((s) => s.persons);
  if (path.points.length < 2) return null;
  const who = personName(Math.min(path.person, persons - 1));
  return (
    <span className="chip" data-testid="path-chip" title={`The next Generate sends this path: ${who} walks it. Then it is cleared.`}>
      <span className="chip__text">
        ↝ {pathLength(path.points).toFixed(1)} m path · next Generate
      </span>
      <button
        type="button"
        className="chip__remove"
        data-testid="path-chip-remove"
        aria-label="Remove the path"
        title="Remove the path"
        onClick={() => setPath({ points: [], preset: null })}
      >
        ×
      </button>
    </span>
  );
}
