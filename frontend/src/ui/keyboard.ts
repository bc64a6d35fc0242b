// Keyboard shortcuts: space play/pause, ←/→ step a frame (shift: 10), Home/End the first /
// last frame, ctrl/cmd+z undo, ctrl/cmd+shift+z (or ctrl+y) redo, ? the shortcut sheet (Esc
// closes it). Ignored while typing in a field. SHORTCUTS is what the sheet lists.
import { useEffect } from "react";
import { redo, undo } from "../directing/actions";
import { playFrom } from "../playback/timeline";
import { frames, playhead, useStudio } from "../store";

export function isTyping(target: EventTarget | null): boolean {
  const el = target as HTMLElement | null;
  if (!el || !el.tagName) return false;
  const tag = el.tagName.toLowerCase();
  if (tag === "textarea" || tag === "select" || el.isContentEditable) return true;
  if (tag !== "input") return false;
  const type = (el as HTMLInputElement).type;
  return !["range", "checkbox", "radio", "button"].includes(type);
}

/** Every shortcut, as the sheet (`?`) shows it. */
export const SHORTCUTS: { keys: string[]; what: string }[] = [
  { keys: ["Space"], what: "Play / pause" },
  { keys: ["←", "→"], what: "One frame back / forward" },
  { keys: ["Shift + ←", "Shift + →"], what: "Ten frames back / forward" },
  { keys: ["Home"], what: "First frame" },
  { keys: ["End"], what: "Last frame" },
  { keys: ["Ctrl + Z"], what: "Undo (the previous version)" },
  { keys: ["Ctrl + Shift + Z", "Ctrl + Y"], what: "Redo" },
  { keys: ["?"], what: "Show or hide these shortcuts" },
  { keys: ["Esc"], what: "Close this sheet" },
];

/** Where Home / End go: the first frame, or the last one received (the clip's last when it is
 * all in). */
export function jumpTarget(key: "Home" | "End", received: number): number {
  return key === "Home" ? 0 : Math.max(0, received - 1);
}

export function onKey(e: KeyboardEvent): void {
  if (isTyping(e.target)) return;
  const s = useStudio.getState();
  const mod = e.ctrlKey || e.metaKey;
  if (e.key === "Escape" && s.shortcuts) {
    e.preventDefault();
    s.setShortcuts(false);
    return;
  }
  if (!mod && e.key === "?") {
    e.preventDefault();
    s.setShortcuts(!s.shortcuts);
    return;
  }
  if (!mod && (e.key === "Home" || e.key === "End")) {
    if (frames.received === 0 || (e.target as HTMLInputElement | null)?.type === "range") return; // the slider jumps itself
    e.preventDefault();
    s.setPlaying(false);
    s.seek(jumpTarget(e.key, frames.received));
    return;
  }
  if (mod && (e.key === "z" || e.key === "Z")) {
    e.preventDefault();
    void (e.shiftKey ? redo() : undo());
  } else if (mod && (e.key === "y" || e.key === "Y")) {
    e.preventDefault();
    void redo();
  } else if (!mod && e.key === " ") {
    if (frames.received === 0) return;
    e.preventDefault();
    if (!s.playing) s.seek(Math.floor(playFrom(playhead.pos, frames.received, frames.total)));
    s.setPlaying(!s.playing);
  } else if (!mod && (e.key === "ArrowLeft" || e.key === "ArrowRight")) {
    if (frames.received === 0 || (e.target as HTMLInputElement | null)?.type === "range") return; // the slider steps itself
    e.preventDefault();
    const step = (e.key === "ArrowLeft" ? -1 : 1) * (e.shiftKey ? 10 : 1);
    s.setPlaying(false);
    s.seek(Math.max(0, Math.min(frames.received - 1, s.frame + step)));
  }
}

export function useKeyboard(): void {
  useEffect(() => {
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  }, []);
}
