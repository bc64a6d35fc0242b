// @vitest-environment node
import { describe, expect, it } from "vitest";
import { exportName, MAX_WORDS_CHARS, slug } from "./filenames";

// the same cases as tests/api/test_export_names.py (the API's Content-Disposition)
const CASES: [string | null, string][] = [
  ["Two people shake hands!", "two-people-shake-hands"],
  ["  a person   walks, then JUMPS twice ", "a-person-walks-then-jumps-twice"],
  ["Café crème — à la française", "cafe-creme-a-la-francaise"],
  ["👋 🙂", ""],
  ["", ""],
  [null, ""],
  ['../../etc/passwd"; rm -rf', "etc-passwd-rm-rf"],
  ["a person walks forward slowly then turns left and waves at a friend across the street", "a-person-walks-forward-slowly-then-turns-left"],
  ["x".repeat(80), "x".repeat(MAX_WORDS_CHARS)],
];

describe("export file names", () => {
  it.each(CASES)("slug(%j) = %j, bounded", (prompt, words) => {
    expect(slug(prompt)).toBe(words);
    expect(slug(prompt).length).toBeLessThanOrEqual(MAX_WORDS_CHARS);
  });

  it("are interplay-<words>-<id>.<ext>", () => {
    expect(exportName("abc", "Two people hug", "glb")).toBe("interplay-two-people-hug-abc.glb");
    expect(exportName("abc", "", "json")).toBe("interplay-abc.json");
    expect(exportName("abc", "a jump", "bvh", "-person2")).toBe("interplay-a-jump-abc-person2.bvh");
  });
});
