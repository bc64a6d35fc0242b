// Which editable body part a joint (or the bone ending at it) belongs to, for click-to-edit:
// arms from the collar down, legs from the hip down, the head (the neck → head bone) the head,
// everything else (the neck's bone spans the upper chest) is the whole body.
import type { EditPart } from "../api/types";

const PREFIXES: [RegExp, EditPart][] = [
  [/^left_(collar|shoulder|elbow|wrist)$/, "left_arm"],
  [/^right_(collar|shoulder|elbow|wrist)$/, "right_arm"],
  [/^left_(hip|knee|ankle|foot)$/, "left_leg"],
  [/^right_(hip|knee|ankle|foot)$/, "right_leg"],
  [/^head$/, "head"],
];

export const PART_LABELS: Record<EditPart, string> = {
  left_arm: "Left arm",
  right_arm: "Right arm",
  left_leg: "Left leg",
  right_leg: "Right leg",
  head: "Head",
  whole_body: "Whole body",
};

export function editPartOfJoint(name: string): EditPart {
  return PREFIXES.find(([re]) => re.test(name))?.[1] ?? "whole_body";
}

/** Joint indices of an edit part (whole body: all of them). */
export function jointsOfPart(joints: string[], part: EditPart): number[] {
  return joints.flatMap((n, j) => (part === "whole_body" || editPartOfJoint(n) === part ? [j] : []));
}
