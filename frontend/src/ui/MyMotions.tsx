import { useEffect, useState } from "react";
import { useShallow } from "zustand/react/shallow";
import type { MotionListItem } from "../api/types";
import { loadMore, refreshLibrary, thisLibraryLink, useLibrary } from "../library";
import { openMotion, showInUrl } from "../studio";
import { useStudio } from "../store";
import { ago, thumbnail } from "./thumbnail";
import { MyJobs } from "./MyJobs";

const PERSON_COLOURS = ["var(--accent-2)", "#f0b45b"];

/** The first frame's skeleton, from the front. */
function PoseThumb({ item, parents }: { item: MotionListItem; parents: number[] }) {
  const t = thumbnail(item.first_frame, parents);
  return (
    <svg className="library__thumb" viewBox={t.viewBox} aria-hidden="true" data-testid="library-thumb">
      {t.lines.map((l, i) => (
        <line key={i} x1={l.x1} y1={l.y1} x2={l.x2} y2={l.y2} stroke={PERSON_COLOURS[l.person % 2]} />
      ))}
    </svg>
  );
}

function what(item: MotionListItem): string | null {
  const e = item.edit;
  if (!item.parent_id || !e) return null;
  if (e.mode === "rerun") return `segment ${(e.segment ?? 0) + 1} re-run`;
  if (e.mode === "react") return "reactor added";
  if (e.trajectory && !e.prompt) return "path";
  return e.prompt ? `edit: ${e.prompt}` : "edit";
}

/** "Open in another browser": the library's link, copied and shown. */
function LibraryLink() {
  const [link, setLink] = useState<{ url: string; copied: boolean } | null>(null);
  const copy = async () => {
    const url = thisLibraryLink();
    let copied = true;
    try {
      await navigator.clipboard.writeText(url);
    } catch {
      copied = false; // no clipboard permission: the link is shown to copy by hand
    }
    setLink({ url, copied });
  };
  return (
    <div className="library__link">
      <button className="link small" data-testid="library-link" onClick={copy} title="A link that opens this list (and adds to it) in another browser">
        Open in another browser…
      </button>
      {link && (
        <>
          <input readOnly value={link.url} data-testid="library-link-url" aria-label="Library link" onFocus={(e) => e.target.select()} />
          <span className="muted small">
            {link.copied ? "Copied. " : ""}Whoever opens this link sees these motions and adds to them: share it only with yourself.
          </span>
        </>
      )}
    </div>
  );
}

/** "My motions": what this browser made, newest first, a page at a time; a click opens one. */
export function MyMotions() {
  const lib = useLibrary(
    useShallow((s) => ({ items: s.items, next: s.next, total: s.total, loaded: s.loaded, loading: s.loading, error: s.error, open: s.open, notice: s.notice, setOpen: s.setOpen })),
  );
  const parents = useStudio((s) => s.skeleton?.parents ?? null);
  const current = useStudio((s) => s.motionId);
  useEffect(() => {
    if (!lib.loaded) void refreshLibrary();
  }, [lib.loaded]);
  const open = (id: string) => {
    if (id === current) return;
    void openMotion(id).then(() => showInUrl(id, "push"));
  };
  return (
    <section className="panel library" aria-labelledby="library-title" data-testid="my-motions">
      <div className="library__head">
        <h2 id="library-title">My motions</h2>
        <button
          className="link small"
          data-testid="library-toggle"
          aria-expanded={lib.open}
          aria-controls="library-list"
          onClick={() => lib.setOpen(!lib.open)}
        >
          {lib.open ? "Hide" : `Show${lib.total ? ` (${lib.total})` : ""}`}
        </button>
      </div>
      {lib.open && (
        <>
          {lib.notice && (
            <p className="small warn library__notice" data-testid="library-notice" role="status">
              {lib.notice}
            </p>
          )}
          <MyJobs />
          {lib.error && <p className="small warn">Could not load your motions: {lib.error}</p>}
          {lib.loaded && !lib.items.length && !lib.error && (
            <p className="muted small" data-testid="library-empty">
              Motions you generate in this browser are listed here, newest first.
            </p>
          )}
          {!lib.loaded && lib.loading && <p className="muted small">Loading…</p>}
          <ol className="library__list" id="library-list" data-testid="library-list">
            {lib.items.map((m) => {
              const tag = what(m);
              return (
                <li key={m.id}>
                  <button
                    className={`library__item${m.id === current ? " library__item--current" : ""}`}
                    data-testid="library-item"
                    data-motion-id={m.id}
                    aria-current={m.id === current ? "true" : undefined}
                    title={m.prompt}
                    onClick={() => open(m.id)}
                  >
                    {parents ? <PoseThumb item={m} parents={parents} /> : <span className="library__thumb" />}
                    <span className="library__text">
                      <span className="library__prompt" data-testid="library-prompt">
                        {m.prompt}
                      </span>
                      <span className="muted small">
                        {m.seconds.toFixed(1)} s · {m.persons === 1 ? "1 person" : `${m.persons} people`}
                        {m.created_at ? ` · ${ago(m.created_at)}` : ""}
                      </span>
                      {tag && <span className="small library__tag">{tag}</span>}
                    </span>
                  </button>
                </li>
              );
            })}
          </ol>
          {lib.items.length > 0 && (
            <p className="muted small library__count" data-testid="library-count">
              {lib.items.length === lib.total ? `All ${lib.total} shown` : `${lib.items.length} of ${lib.total} shown`}
            </p>
          )}
          {lib.next && (
            <button className="small" data-testid="library-more" onClick={() => void loadMore()} disabled={lib.loading}>
              {lib.loading ? "Loading…" : `Show ${Math.min(20, lib.total - lib.items.length)} more`}
            </button>
          )}
          {lib.items.length > 0 && <LibraryLink />}
        </>
      )}
    </section>
  );
}
