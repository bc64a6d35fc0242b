// The prompt form's checks against the API's limits (api/limits.ts, read from its schema), and
// any error message turned into plain sentences for the banner. Pure: the prompt bar and the
// error banner render what these answer.
import type { Limits } from "./limits";

export interface FormValues {
  prompt: string;
  seconds: number;
  persons: number;
}

export type FormField = "prompt" | "seconds" | "persons";

export interface FormProblem {
  field: FormField;
  message: string;
}

/** The prompt's length as the server counts it: runs of whitespace are one space, none at the ends. */
export function promptLength(prompt: string): number {
  return prompt.trim().replace(/\s+/g, " ").length;
}

const fmt = (n: number) => (Number.isInteger(n) ? String(n) : n.toFixed(2).replace(/0+$/, ""));

/** What keeps the form from being sent, in plain sentences (none: it may be sent). */
export function formProblems(v: FormValues, limits: Limits): FormProblem[] {
  const out: FormProblem[] = [];
  const length = promptLength(v.prompt);
  if (length === 0) out.push({ field: "prompt", message: "Type what the people do first." });
  else if (length > limits.promptMax) {
    out.push({
      field: "prompt",
      message: `The prompt is ${length.toLocaleString("en")} characters long; the limit is ${limits.promptMax}. Shorten it by ${(length - limits.promptMax).toLocaleString("en")}.`,
    });
  }
  const { secondsMin: lo, secondsMax: hi } = limits;
  if (!Number.isFinite(v.seconds)) out.push({ field: "seconds", message: `Give the length in seconds, from ${fmt(lo)} to ${fmt(hi)}.` });
  else if (v.seconds < lo || v.seconds > hi) {
    out.push({ field: "seconds", message: `The length must be from ${fmt(lo)} to ${fmt(hi)} seconds; ${fmt(v.seconds)} is ${v.seconds < lo ? "too short" : "too long"}.` });
  }
  if (!Number.isInteger(v.persons) || v.persons < 1 || v.persons > limits.personsMax) {
    out.push({ field: "persons", message: `A motion has 1 to ${limits.personsMax} people.` });
  }
  return out;
}

// pydantic's wording (an older server, or a message nested in another) → plain words, as the
// API's own (backend/interplay/pipeline/messages.py)
const WORDS: [RegExp, string][] = [
  [/Value error, /g, ""],
  [/Input should be less than or equal to /g, "must be at most "],
  [/Input should be greater than or equal to /g, "must be at least "],
  [/Input should be less than /g, "must be less than "],
  [/Input should be greater than /g, "must be more than "],
  [/Input should be a valid integer[^;]*/g, "must be a whole number"],
  [/Input should be a valid number[^;]*/g, "must be a number"],
  [/Input should be a finite number/g, "must be a finite number"],
  [/Input should be a valid string/g, "must be text"],
  [/Input should be /g, "must be "],
  [/String should have at most (\d+) characters?/g, "must be at most $1 characters long"],
  [/Field required/g, "is required"],
  [/(\w[\w.]*): (must|is|has) /g, "$1 $2 "],
];

/** The page's names for the API's fields (the first word of a message). */
const FIELDS: Record<string, string> = {
  prompt: "The prompt",
  seconds: "The length in seconds",
  persons: "The number of people",
  seed: "The seed",
  trajectory: "The path",
  "trajectory.points": "The path's points",
  "trajectory.person": "The person following the path",
  part: "The body part",
  frames: "The frame range",
  limit: "The page size",
  after: "The page",
  fps: "The frame rate",
  format: "The export format",
};

const FIELD_AT_START = /^([a-z_]+(?:\.[a-z0-9_]+)*)(:\s+|\s+(?=(?:must|is|has|should|needs)\b))/;

function sentence(part: string): string {
  let s = part.trim();
  for (const [re, to] of WORDS) s = s.replace(re, to);
  const m = FIELD_AT_START.exec(s);
  if (m) {
    const label = FIELDS[m[1]] ?? FIELDS[m[1].replace(/\.\d+(\.\d+)*$/, "")];
    if (label) s = `${label}${m[2].startsWith(":") ? ": " : " "}${s.slice(m[0].length)}`;
  }
  s = s.replace(/^X-Interplay-Client: /, "This browser's id ");
  if (!s) return "";
  s = s[0].toUpperCase() + s.slice(1);
  return /[.!?]$/.test(s) ? s : `${s}.`;
}

/** An error message (the API's `detail`, a network failure, a stream error) as plain sentences:
 * each "; "-separated part capitalised and ended, the field named as the page names it, and
 * pydantic's wording ("Input should be …") replaced. */
export function plainError(message: string): string {
  const parts = message
    .split(/;\s+(?=[A-Za-z_-]+(?:\.[a-z0-9_]+)*(?::|\s+(?:must|is|has)\b))/)
    .map(sentence)
    .filter(Boolean);
  return parts.join(" ") || "Something went wrong.";
}
