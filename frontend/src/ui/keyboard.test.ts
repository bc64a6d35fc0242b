// @vitest-environment node
import { describe, expect, it } from "vitest";
import { SHORTCUTS, isTyping, jumpTarget } from "./keyboard";

const el = (tagName: string, type = "", isContentEditable = false) => ({ tagName, type, isContentEditable }) as unknown as EventTarget;

describe("isTyping", () => {
  it("is true in text fields, false on sliders, buttons and the page", () => {
    expect(isTyping(el("INPUT", "text"))).toBe(true);
    expect(isTyping(el("INPUT", "number"))).toBe(true);
    expect(isTyping(el("TEXTAREA"))).toBe(true);
    expect(isTyping(el("DIV", "", true))).toBe(true);
    expect(isTyping(el("INPUT", "range"))).toBe(false);
    expect(isTyping(el("BUTTON"))).toBe(false);
    expect(isTyping(null)).toBe(false);
  });
});

describe("Home / End and the shortcut sheet", () => {
  it("jump to the first frame and to the last frame received", () => {
    expect(jumpTarget("Home", 80)).toBe(0);
    expect(jumpTarget("End", 80)).toBe(79);
    expect(jumpTarget("End", 0)).toBe(0);
  });

  it("the sheet lists every key the handler takes", () => {
    const keys = SHORTCUTS.flatMap((s) => s.keys).join(" ");
    for (const k of ["Space", "←", "→", "Home", "End", "Ctrl + Z", "Ctrl + Y", "?", "Esc"]) expect(keys).toContain(k);
  });
});
