import { useState } from "react";
import { exportUrl, shareUrl } from "../api/client";
import { useStudio } from "../store";
import { personName } from "./format";

/** Share link (copied to the clipboard and shown) and downloads: BVH per person, JSON, GLB
 * (everyone in one file). */
export function ShareExport() {
  const motionId = useStudio((s) => s.motionId);
  const persons = useStudio((s) => s.motionPersons);
  const done = useStudio((s) => s.stream.phase === "done");
  const [copied, setCopied] = useState<{ id: string; url: string; ok: boolean } | null>(null);
  const ready = Boolean(motionId && done);
  const link = copied && copied.id === motionId ? copied : null;

  const share = async () => {
    if (!motionId) return;
    const url = shareUrl(motionId);
    let ok = true;
    try {
      await navigator.clipboard.writeText(url);
    } catch {
      ok = false; // no clipboard permission: the link is still shown to copy by hand
    }
    setCopied({ id: motionId, url, ok });
  };

  /** Both people of the scene: two downloads (one BVH per person, the same frame of reference). */
  const downloadBoth = () => {
    if (!motionId) return;
    for (let p = 0; p < persons; p++) {
      const a = document.createElement("a");
      a.href = exportUrl(motionId, "bvh", p);
      a.download = `interplay-${motionId}-person${p + 1}.bvh`; // Person 1 → person1 (the API names it so too)
      document.body.appendChild(a);
      a.click();
      a.remove();
    }
  };

  return (
    <section className="panel" aria-labelledby="share-title">
      <h2 id="share-title">Share &amp; export</h2>
      <div className="button-row">
        <button data-testid="share" onClick={share} disabled={!ready}>
          Share link
        </button>
        {Array.from({ length: ready ? persons : 1 }, (_, p) => (
          <a
            key={p}
            className={`button${ready ? "" : " disabled"}`}
            data-testid={`export-bvh-${p}`}
            href={ready && motionId ? exportUrl(motionId, "bvh", p) : undefined}
            aria-disabled={!ready}
            download
          >
            BVH{persons === 2 ? ` · ${personName(p)}` : ""}
          </a>
        ))}
        {ready && persons === 2 && (
          <button data-testid="export-bvh-both" onClick={downloadBoth} title="Both people: one BVH file each">
            BVH · both
          </button>
        )}
        <a
          className={`button${ready ? "" : " disabled"}`}
          data-testid="export-json"
          href={ready && motionId ? exportUrl(motionId, "json") : undefined}
          aria-disabled={!ready}
          download
        >
          JSON
        </a>
        <a
          className={`button${ready ? "" : " disabled"}`}
          data-testid="export-glb"
          href={ready && motionId ? exportUrl(motionId, "glb") : undefined}
          aria-disabled={!ready}
          aria-label="Download GLB"
          title="glTF binary: a skinned character per person and one animation for everyone (Blender, Unity, Unreal, three.js)"
          download
        >
          GLB
        </a>
      </div>
      {link && (
        <div className="share-link">
          <input readOnly value={link.url} data-testid="share-url" aria-label="Share link" onFocus={(e) => e.target.select()} />
          <span className="muted small">{link.ok ? "Copied to the clipboard." : "Copy this link."}</span>
        </div>
      )}
    </section>
  );
}
