// Download names: `interplay-<prompt words>-<id>.<ext>` — the API's Content-Disposition
// (backend/interplay/api/filenames.py) and the studio's `download` names are the same function:
// the prompt's words slugified (ASCII letters and digits, lower case, joined by "-", accents
// folded, the rest dropped), at most MAX_WORDS_CHARS characters, cut at a word boundary.

export const MAX_WORDS_CHARS = 48;

/** "Two people shake hands!" → "two-people-shake-hands" ("" when nothing is left). */
export function slug(prompt: string | null | undefined, limit = MAX_WORDS_CHARS): string {
  const ascii = (prompt ?? "").normalize("NFKD").replace(/[^\x00-\x7f]/g, "");
  const words = ascii.toLowerCase().match(/[a-z0-9]+/g) ?? [];
  let out = "";
  for (const word of words) {
    const joined = out ? `${out}-${word}` : word;
    if (joined.length > limit) {
      if (!out) out = word.slice(0, limit); // one very long word: cut it
      break;
    }
    out = joined;
  }
  return out;
}

/** `interplay-<slug>-<id><suffix>.<ext>`; `suffix` such as "-person1" or "-skeleton". */
export function exportName(id: string, prompt: string | null | undefined, ext: string, suffix = ""): string {
  const words = slug(prompt);
  return `interplay-${words ? `${words}-` : ""}${id}${suffix}.${ext}`;
}
