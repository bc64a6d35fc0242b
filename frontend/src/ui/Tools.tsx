import { useEffect, useRef } from "react";
import { pathLength } from "../directing/path";
import { pointer, useStudio, type Tool } from "../store";
import { shownPath, useFollowed } from "../directing/followed";
import { FigureToggle } from "./FigureToggle";

const TOOLS: { tool: Tool; label: string; hint: string }[] = [
  { tool: "path", label: "✎ Draw path", hint: "Drag on the floor to draw a path for a person to follow" },
  { tool: "part", label: "☝ Edit part", hint: "Hover a body part, click it to edit it with an instruction" },
];

/** The length of the path being drawn, updated as the pointer moves (read from `pointer` in
 * its own animation frame loop while the path tool is on, not through React state), or of the
 * path drawn. */
function PathLength() {
  const el = useRef<HTMLSpanElement>(null);
  const points = useStudio((s) => s.path.points);
  useEffect(() => {
    let raf = 0;
    let version = -1;
    const tick = () => {
      raf = requestAnimationFrame(tick);
      if (pointer.version === version || !el.current) return;
      version = pointer.version;
      const drawing = pointer.drawing;
      const pts = drawing ?? useStudio.getState().path.points;
      el.current.textContent = pts.length >= 2 ? `${drawing ? "drawing · " : ""}${pathLength(pts).toFixed(1)} m` : "";
      el.current.dataset.drawing = drawing ? "1" : "0";
    };
    raf = requestAnimationFrame(tick);
    return () => cancelAnimationFrame(raf);
  }, []);
  useEffect(() => {
    pointer.version++; // redraw the label for a path set by a preset or cleared
  }, [points]);
  return <span ref={el} className="tools__length small" data-testid="path-length-live" aria-live="off" />;
}

/** Show / hide the path the motion on stage followed (kept on the floor after generating). */
function FollowedToggle() {
  const followed = useFollowed((f) => f.path);
  const show = useFollowed((f) => f.show);
  const setShow = useFollowed((f) => f.setShow);
  const relevant = useStudio((s) => shownPath({ person: 0, points: [] }, followed, true, s.motionId, s.versions.ids).followed);
  if (!relevant) return null;
  return (
    <button
      data-testid="path-visible"
      aria-pressed={show}
      className={show ? "active" : ""}
      title={show ? "Hide the path this motion followed" : "Show the path this motion followed"}
      onClick={() => setShow(!show)}
    >
      ↝ Path
    </button>
  );
}

/** The viewport's modes: draw a path on the floor (with a top view and the path's length as it
 * is drawn), or pick a body part to edit. */
export function Tools() {
  const tool = useStudio((s) => s.tool);
  const setTool = useStudio((s) => s.setTool);
  const topView = useStudio((s) => s.topView);
  const setTopView = useStudio((s) => s.setTopView);
  return (
    <div className="tools" role="toolbar" aria-label="Directing tools">
      {TOOLS.map((t) => (
        <button
          key={t.tool}
          data-testid={`tool-${t.tool}`}
          aria-pressed={tool === t.tool}
          className={tool === t.tool ? "active" : ""}
          title={t.hint}
          onClick={() => setTool(t.tool)}
        >
          {t.label}
        </button>
      ))}
      {tool === "path" && (
        <>
          <button
            data-testid="top-view"
            aria-pressed={topView}
            className={topView ? "active" : ""}
            title="Look straight down on the floor to draw (off: draw in the 3D view)"
            onClick={() => setTopView(!topView)}
          >
            ⊤ Top view
          </button>
          <PathLength />
        </>
      )}
      <FollowedToggle />
      {tool !== "view" && <span className="tools__hint small">{TOOLS.find((t) => t.tool === tool)?.hint}</span>}
      <FigureToggle />
    </div>
  );
}
