// Keyboard shortcuts: space play/pause, ←/→ step a frame (shift: 10), ctrl/cmd+z undo,
// ctrl/cmd+shift+z (or ctrl+y) redo. Ignored while typing in a field.
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

export function onKey(e: KeyboardEvent): void {
  if (isTyping(e.target)) return;
  const s = useStudio.getState();
  const mod = e.ctrlKey || e.metaKey;
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
