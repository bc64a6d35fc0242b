import { CONTACT_COLOUR, PENETRATION_COLOUR, partColour } from "../scene/colours";
import { useStudio } from "../store";

const PART_LABELS: Record<string, string> = {
  left_upper: "Left upper",
  right_upper: "Right upper",
  left_lower: "Left lower",
  right_lower: "Right lower",
};

/** Colour key: the four body parts (per person), contact joints and the penetration marks
 * (red dots with a halo where two bodies overlap). */
export function Legend() {
  const skeleton = useStudio((s) => s.skeleton);
  const persons = useStudio((s) => s.motionPersons);
  if (!skeleton) return null;
  const parts = Object.keys(skeleton.parts);
  const people = persons === 2 ? [0, 1] : [0];
  return (
    <div className="legend" data-testid="legend" aria-label="Colour legend">
      {people.map((p) => (
        <div className="legend__row" key={p}>
          {people.length > 1 && <span className="legend__person">Person {p + 1}</span>}
          {parts.map((part) => (
            <span className="legend__item" key={part}>
              <i style={{ background: partColour(skeleton, part, p) }} />
              {PART_LABELS[part] ?? part.replace("_", " ")}
            </span>
          ))}
        </div>
      ))}
      <div className="legend__row">
        <span className="legend__item" title="A hand touching the other person, or a foot coming down (feet resting on the floor do not glow)">
          <i className="round" style={{ background: CONTACT_COLOUR }} />
          Contact
        </span>
        <span className="legend__item">
          <i className="round" style={{ background: PENETRATION_COLOUR, boxShadow: `0 0 0 3px ${PENETRATION_COLOUR}55` }} />
          Penetration (where the bodies overlap)
        </span>
      </div>
    </div>
  );
}
