import { useStudio } from "../store";
import { VIEW_PRESETS, requestView } from "../scene/views";

/** The camera's preset views, over the viewport's lower right (a column; on a phone a row): front, side, top, frame both
 * (everyone fitted, the direction kept) and reset (the opening view). A click moves the
 * camera once (the render loop takes the request); orbiting afterwards is the user's. Off
 * while the path tool owns the camera (its own top view) and before there is a motion. */
export function ViewButtons() {
  const persons = useStudio((s) => s.motionPersons);
  const tool = useStudio((s) => s.tool);
  const disabled = persons === 0 || tool === "path";
  return (
    <div className="views" role="toolbar" aria-label="Camera views" data-testid="views">
      {VIEW_PRESETS.map((v) => (
        <button
          key={v.preset}
          type="button"
          className="views__button"
          data-testid={`view-${v.preset}`}
          aria-label={v.preset === "fit" && persons < 2 ? "Frame the person" : v.name}
          title={v.hint}
          disabled={disabled}
          onClick={() => requestView(v.preset)}
        >
          {v.preset === "fit" && persons < 2 ? "Frame" : v.label}
        </button>
      ))}
    </div>
  );
}
