import { useEffect, useMemo, useRef } from "react";
import { useShallow } from "zustand/react/shallow";
import { timelineMarks } from "../directing/marks";
import { framePercent, xToFrame } from "../playback/timeline";
import { FPS, frames, useStudio } from "../store";

const PLOT_MAX = 1.0; // metres at the top of the distance plot

/** The playhead: a line at the frame shown (its own component, so only it re-renders as the
 * frame changes). */
function Playhead({ total }: { total: number }) {
  const frame = useStudio((s) => s.frame);
  return <div className="track__playhead" data-testid="playhead" data-frame={frame} style={{ left: framePercent(frame, total) }} />;
}

/** Right above the scrubber, in the same lane and with the same mapping (inset by half the
 * scrubber's thumb each side): the plan's segments, penetration / contact marks (click to jump),
 * the per-frame minimum distance between the two people, the frame range selected by dragging,
 * and the playhead. */
export function TimelineTrack() {
  const s = useStudio(
    useShallow((s) => ({
      received: s.stream.received,
      total: s.stream.total,
      phase: s.stream.phase,
      segments: s.stream.plan?.segments,
      motionId: s.motionId,
      persons: s.motionPersons,
      range: s.range,
      setRange: s.setRange,
      seek: s.seek,
      setPlaying: s.setPlaying,
    })),
  );
  const track = useRef<HTMLDivElement>(null);
  const plot = useRef<HTMLCanvasElement>(null);
  const drag = useRef<{ from: number; moved: boolean } | null>(null);
  const total = s.total;
  // highlights arrive with the frames: recompute when more frames are in or the motion changes
  const marks = useMemo(
    () => timelineMarks(frames.received, frames.penetration, frames.contacts, frames.minDistance, frames.persons),
    // eslint-disable-next-line react-hooks/exhaustive-deps
    [s.received, s.phase, s.motionId],
  );

  useEffect(() => {
    const c = plot.current;
    if (!c) return;
    const w = (c.width = c.clientWidth || 1);
    const h = (c.height = c.clientHeight || 1);
    const ctx = c.getContext("2d");
    if (!ctx) return;
    ctx.clearRect(0, 0, w, h);
    if (frames.persons < 2 || total < 2) return;
    ctx.strokeStyle = getComputedStyle(c).color;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    let started = false;
    for (let t = 0; t < frames.received; t++) {
      const d = frames.minDistance[t];
      if (d === undefined || !Number.isFinite(d)) continue;
      const x = (t / (total - 1)) * w; // the canvas spans the inset box: the scrubber's mapping
      const y = h - (Math.min(PLOT_MAX, Math.max(0, d)) / PLOT_MAX) * (h - 2) - 1;
      if (started) ctx.lineTo(x, y);
      else ctx.moveTo(x, y);
      started = true;
    }
    ctx.stroke();
  }, [s.received, s.phase, s.motionId, total]);

  if (total === 0) return <div className="track track--empty" data-testid="track" />;

  const frameAt = (clientX: number) => {
    const r = track.current!.getBoundingClientRect();
    return xToFrame(clientX, total, r.left, r.width);
  };
  const pct = (f: number) => framePercent(f, total);
  const jump = (f: number) => {
    s.setPlaying(false);
    s.seek(Math.min(f, Math.max(0, s.received - 1)));
  };
  const segments = (s.segments ?? []).filter((g) => g.end > g.start && g.start < total);

  return (
    <div
      className="track"
      ref={track}
      data-testid="track"
      title="Drag to select frames for an edit; click to jump"
      onPointerDown={(e) => {
        if ((e.target as HTMLElement).closest("button")) return;
        e.currentTarget.setPointerCapture?.(e.pointerId);
        drag.current = { from: frameAt(e.clientX), moved: false };
      }}
      onPointerMove={(e) => {
        const d = drag.current;
        if (!d) return;
        const f = frameAt(e.clientX);
        if (Math.abs(f - d.from) >= 2) d.moved = true;
        if (d.moved) s.setRange([Math.min(d.from, f), Math.max(d.from, f) + 1]);
      }}
      onPointerUp={(e) => {
        const d = drag.current;
        drag.current = null;
        if (d && !d.moved) jump(frameAt(e.clientX));
      }}
    >
      <div className="track__inner">
        {segments.length > 1 &&
          segments.map((g, i) => (
            <div
              key={i}
              className={`track__segment${i % 2 ? " track__segment--odd" : ""}`}
              data-testid={`track-segment-${i}`}
              data-start={g.start}
              style={{ left: pct(g.start), width: framePercent(Math.min(g.end, total - 1) - g.start, total) }}
              title={`Segment ${i + 1}: ${g.prompt} · ${(g.start / FPS).toFixed(1)}–${(g.end / FPS).toFixed(1)} s`}
            >
              <span className="track__segment-label">{i + 1}</span>
            </div>
          ))}
        <canvas ref={plot} className="track__plot" data-testid="distance-plot" aria-label="Minimum distance between the people" />
        {!s.range && !marks.length && s.persons < 2 && segments.length < 2 && (
          <span className="track__hint small">drag here to select frames for an edit</span>
        )}
        {s.range && (
          <div
            className="track__range"
            data-testid="track-range"
            style={{ left: pct(s.range[0]), width: `calc(${framePercent(s.range[1] - 1 - s.range[0], total)} + 2px)` }}
          />
        )}
        {marks.map((m) => (
          <button
            key={`${m.kind}-${m.start}`}
            className={`track__mark track__mark--${m.kind}`}
            data-testid={`mark-${m.kind}`}
            data-frame={m.start}
            style={{ left: pct(m.start), width: `max(6px, ${framePercent(m.end - 1 - m.start, total)})` }}
            title={`${m.kind} · frames ${m.start}–${m.end - 1}`}
            aria-label={`${m.kind} at frame ${m.start}`}
            onClick={() => jump(m.start)}
          />
        ))}
        <Playhead total={total} />
      </div>
    </div>
  );
}
