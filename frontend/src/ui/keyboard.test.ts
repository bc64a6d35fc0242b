// @vitest-environment node
import { describe, expect, it } from "vitest";
import { isTyping } from "./keyboard";

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
