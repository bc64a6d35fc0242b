import { useState } from "react";
import { useShallow } from "zustand/react/shallow";
import { shareUrl } from "../api/client";
import { redo, undo } from "../directing/actions";
import { canRedo, canUndo } from "../directing/versions";
import { useStudio } from "../store";

/** Undo / redo between versions (each edit is one), and a link to the current version. */
export function Versions() {
  const s = useStudio(useShallow((s) => ({ versions: s.versions, editing: s.editing, motionId: s.motionId })));
  const [copied, setCopied] = useState<string | null>(null);
  const { versions } = s;
  const copy = async () => {
    if (!s.motionId) return;
    const url = shareUrl(s.motionId);
    try {
      await navigator.clipboard.writeText(url);
      setCopied(s.motionId);
    } catch {
      setCopied(null);
      window.prompt("Copy this link", url);
    }
  };
  return (
    <div className="versions" data-testid="versions">
      <button
        className="icon-button"
        data-testid="undo"
        aria-label="Undo (Ctrl+Z)"
        title="Undo (Ctrl+Z)"
        disabled={!canUndo(versions) || s.editing}
        onClick={() => void undo()}
      >
        ↶
      </button>
      <button
        className="icon-button"
        data-testid="redo"
        aria-label="Redo (Ctrl+Shift+Z)"
        title="Redo (Ctrl+Shift+Z)"
        disabled={!canRedo(versions) || s.editing}
        onClick={() => void redo()}
      >
        ↷
      </button>
      <span className="small muted" data-testid="version-label">
        {versions.ids.length ? `v${versions.index + 1} / ${versions.ids.length}` : "no versions"}
      </span>
      <button
        data-testid="copy-link"
        className="versions__copy"
        disabled={!s.motionId}
        onClick={() => void copy()}
        title="Copy a link to this version"
        aria-label={copied && copied === s.motionId ? "Link copied" : "Copy link"}
      >
        <span className="versions__copy-text">{copied && copied === s.motionId ? "Copied ✓" : "Copy link"}</span>
        <span className="versions__copy-icon" aria-hidden="true">
          {copied && copied === s.motionId ? "✓" : "Link"}
        </span>
      </button>
    </div>
  );
}
