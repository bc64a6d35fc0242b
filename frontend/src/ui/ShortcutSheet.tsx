import { useEffect, useRef } from "react";
import { useStudio } from "../store";
import { SHORTCUTS } from "./keyboard";

/** The keyboard shortcuts (`?` opens and closes it, Esc or a click outside closes it). */
export function ShortcutSheet() {
  const open = useStudio((s) => s.shortcuts);
  const setOpen = useStudio((s) => s.setShortcuts);
  const close = useRef<HTMLButtonElement>(null);
  useEffect(() => {
    if (open) close.current?.focus();
  }, [open]);
  if (!open) return null;
  return (
    <div className="sheet-backdrop" data-testid="shortcuts-backdrop" onClick={(e) => e.target === e.currentTarget && setOpen(false)}>
      <section className="sheet" role="dialog" aria-modal="true" aria-labelledby="shortcuts-title" data-testid="shortcuts">
        <div className="sheet__head">
          <h2 id="shortcuts-title">Keyboard shortcuts</h2>
          <button ref={close} className="icon-button" aria-label="Close (Esc)" title="Close (Esc)" onClick={() => setOpen(false)}>
            ×
          </button>
        </div>
        <dl className="sheet__list">
          {SHORTCUTS.map((s) => (
            <div key={s.what} className="sheet__row">
              <dt>
                {s.keys.map((k, i) => (
                  <span key={k}>
                    {i > 0 && <span className="muted"> or </span>}
                    <kbd>{k}</kbd>
                  </span>
                ))}
              </dt>
              <dd>{s.what}</dd>
            </div>
          ))}
        </dl>
        <p className="muted small">Shortcuts do nothing while you type in a field.</p>
      </section>
    </div>
  );
}

/** The header's "?" button that opens the sheet. */
export function ShortcutButton() {
  const setOpen = useStudio((s) => s.setShortcuts);
  return (
    <button className="icon-button" data-testid="shortcuts-button" aria-label="Keyboard shortcuts (?)" title="Keyboard shortcuts (?)" onClick={() => setOpen(true)}>
      ?
    </button>
  );
}
