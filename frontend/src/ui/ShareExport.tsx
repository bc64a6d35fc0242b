import { useState } from "react";
import { exportUrl, shareUrl } from "../api/client";
import { exportName } from "../api/filenames";
import { useStudio } from "../store";
import { DEFAULT_PRESETS, FPS_CHOICES, type Presets, describePresets, withPresets } from "./exportPresets";
import { personName } from "./format";

/** Share link (copied to the clipboard and shown) and downloads: BVH per person, JSON, GLB
 * (everyone in one file), with the presets (frame rate, units, joint names; BVH's up axis)
 * chosen under "Presets". */
export function ShareExport() {
  const motionId = useStudio((s) => s.motionId);
  const persons = useStudio((s) => s.motionPersons);
  const done = useStudio((s) => s.stream.phase === "done");
  // the motion's prompt (its plan's; the form may have been edited since) names the downloads,
  // as the API's Content-Disposition does: interplay-<prompt words>-<id>.<ext>
  const named = useStudio((s) => (typeof s.stream.plan?.prompt === "string" ? s.stream.plan.prompt : s.prompt));
  const fileName = (ext: string, suffix = "") => (motionId ? exportName(motionId, named, ext, suffix) : undefined);
  const [copied, setCopied] = useState<{ id: string; url: string; ok: boolean } | null>(null);
  const [presets, setPresets] = useState<Presets>(DEFAULT_PRESETS);
  const bvhUrl = (id: string, p: number) => withPresets(exportUrl(id, "bvh", p), "bvh", presets);
  const glbUrl = (id: string) => withPresets(exportUrl(id, "glb"), "glb", presets);
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
      a.href = bvhUrl(motionId, p);
      a.download = exportName(motionId, named, "bvh", `-person${p + 1}`); // Person 1 → person1 (the API names it so too)
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
            href={ready && motionId ? bvhUrl(motionId, p) : undefined}
            aria-disabled={!ready}
            title={`BVH: ${describePresets(presets, "bvh")}`}
            download={fileName("bvh", `-person${p + 1}`)}
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
          download={fileName("json")}
        >
          JSON
        </a>
        <a
          className={`button${ready ? "" : " disabled"}`}
          data-testid="export-glb"
          href={ready && motionId ? glbUrl(motionId) : undefined}
          aria-disabled={!ready}
          aria-label="Download GLB"
          title={`glTF binary: a skinned character per person and one animation for everyone (Blender, Unity, Unreal, three.js); ${describePresets(presets, "glb")}`}
          download={fileName("glb")}
        >
          GLB
        </a>
      </div>
      <details className="export-presets" data-testid="export-presets">
        <summary className="muted small">Presets: {describePresets(presets, "bvh")}</summary>
        <div className="button-row">
          <label>
            fps{" "}
            <select data-testid="preset-fps" value={presets.fps}
              onChange={(e) => setPresets({ ...presets, fps: Number(e.target.value) as Presets["fps"] })}>
              {FPS_CHOICES.map((f) => <option key={f} value={f}>{f}</option>)}
            </select>
          </label>
          <label>
            units{" "}
            <select data-testid="preset-units" value={presets.units}
              onChange={(e) => setPresets({ ...presets, units: e.target.value as Presets["units"] })}>
              <option value="m">m</option>
              <option value="cm">cm</option>
            </select>
          </label>
          <label>
            names{" "}
            <select data-testid="preset-names" value={presets.names}
              onChange={(e) => setPresets({ ...presets, names: e.target.value as Presets["names"] })}>
              <option value="smpl">SMPL</option>
              <option value="mixamo">Mixamo</option>
            </select>
          </label>
          <label title="BVH only: glTF is Y up">
            up (BVH){" "}
            <select data-testid="preset-up" value={presets.up}
              onChange={(e) => setPresets({ ...presets, up: e.target.value as Presets["up"] })}>
              <option value="y">Y</option>
              <option value="z">Z (Blender)</option>
            </select>
          </label>
        </div>
      </details>
      {link && (
        <div className="share-link">
          <input readOnly value={link.url} data-testid="share-url" aria-label="Share link" onFocus={(e) => e.target.select()} />
          <span className="muted small">{link.ok ? "Copied to the clipboard." : "Copy this link."}</span>
        </div>
      )}
    </section>
  );
}
