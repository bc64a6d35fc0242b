import { describe, expect, it } from "vitest";
import { cpuSkinning, initialFigure } from "./figure";

describe("the figure a page starts with", () => {
  it("is the remembered one, the mannequin by default", () => {
    expect(initialFigure("", null)).toBe("mannequin");
    expect(initialFigure("", "character")).toBe("character");
    expect(initialFigure("", "something else")).toBe("mannequin");
  });

  it("is ?figure= when it names one (for this page: the perf spec, a shared look)", () => {
    expect(initialFigure("?figure=character", "mannequin")).toBe("character");
    expect(initialFigure("?quality=light&figure=mannequin", "character")).toBe("mannequin");
    expect(initialFigure("?figure=robot", "character")).toBe("character");
  });
});

describe("where the character is skinned", () => {
  it("on the CPU in light quality, in the vertex shader in full; ?skin= decides when given", () => {
    expect(cpuSkinning("light", null)).toBe(true);
    expect(cpuSkinning("full", null)).toBe(false);
    expect(cpuSkinning("light", "gpu")).toBe(false);
    expect(cpuSkinning("full", "cpu")).toBe(true);
  });
});
