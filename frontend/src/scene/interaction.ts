// Pointer gestures on the viewport: in "path" mode drag on the floor to draw a path (or drag a
// handle to move a point); in "part" mode hovering highlights the body part under the pointer
// and a click selects it. Per-move state lives in `pointer` (not React state).
import { editPartOfJoint } from "../directing/parts";
import { thinPoints, type Point } from "../directing/path";
import { pointer, useStudio } from "../store";
import { Picker } from "./Picker";
import type { Stage } from "./Stage";

const CLICK_SLOP = 4; // px: a press that moves less is a click, not an orbit

export function attachPointer(stage: Stage, canvas: HTMLCanvasElement): () => void {
  const picker = new Picker(canvas, stage.camera);
  let down: { x: number; y: number; handle: number | null } | null = null;

  const partAt = (e: PointerEvent) => {
    const s = useStudio.getState();
    const hit = picker.joint(e.clientX, e.clientY, stage.pickable);
    if (!hit || !s.skeleton) return null;
    return { person: hit.person, part: editPartOfJoint(s.skeleton.joints[hit.joint]) };
  };

  const onDown = (e: PointerEvent) => {
    const s = useStudio.getState();
    down = { x: e.clientX, y: e.clientY, handle: null };
    if (s.tool !== "path" || e.button !== 0) return;
    canvas.setPointerCapture?.(e.pointerId);
    down.handle = picker.handle(e.clientX, e.clientY, stage.path.handles);
    if (down.handle === null) {
      const g = picker.ground(e.clientX, e.clientY);
      pointer.drawing = g ? [g] : [];
      pointer.version++;
    }
  };

  const onMove = (e: PointerEvent) => {
    const s = useStudio.getState();
    if (s.tool === "path" && down) {
      const g = picker.ground(e.clientX, e.clientY);
      if (!g) return;
      if (down.handle !== null) {
        const points = s.path.points.map((p, i) => (i === down!.handle ? g : p)) as Point[];
        s.setPath({ points }); // stays a preset: its points keep their handles
      } else if (pointer.drawing) {
        pointer.drawing.push(g);
        pointer.version++;
      }
    } else if (s.tool === "part" && !down) {
      const hover = partAt(e);
      const same = hover?.person === pointer.hover?.person && hover?.part === pointer.hover?.part;
      if (!same) {
        pointer.hover = hover;
        pointer.version++;
        canvas.style.cursor = hover ? "pointer" : "";
      }
    }
  };

  const onUp = (e: PointerEvent) => {
    const s = useStudio.getState();
    const moved = down ? Math.hypot(e.clientX - down.x, e.clientY - down.y) : 0;
    if (s.tool === "path" && pointer.drawing) {
      const points = thinPoints(pointer.drawing);
      pointer.drawing = null;
      if (points.length >= 2) s.setPath({ points, preset: null });
      else pointer.version++;
    } else if (s.tool === "part" && down && moved < CLICK_SLOP) {
      s.select(partAt(e));
    }
    down = null;
  };

  const onLeave = () => {
    if (pointer.hover) {
      pointer.hover = null;
      pointer.version++;
    }
  };

  canvas.addEventListener("pointerdown", onDown);
  canvas.addEventListener("pointermove", onMove);
  canvas.addEventListener("pointerup", onUp);
  canvas.addEventListener("pointerleave", onLeave);
  return () => {
    canvas.removeEventListener("pointerdown", onDown);
    canvas.removeEventListener("pointermove", onMove);
    canvas.removeEventListener("pointerup", onUp);
    canvas.removeEventListener("pointerleave", onLeave);
  };
}
