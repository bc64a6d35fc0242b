import { useEffect, useMemo, useRef } from "react";
import { useShallow } from "zustand/react/shallow";
import { timelineMarks } from "../directing/marks";
import { frames, useStudio } from "../store";

const PLOT_MAX = 1.0; // metres at the top of the distance plot

/** Above the scrubber: penetration / contact marks (click to jump), the per-frame minimum
 * distance between the two people, and the frame range selected by dragging. */
export function TimelineTrack() {
  const s = useStudio(
    useShallow((s) => ({
      received: s.stream.received,
      total: s.stream.total,
      phase: s.stream.phase,
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
      const x = (t / (total - 1)) * w;
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
    const f = Math.round(((clientX - r.left) / r.width) * (total - 1));
    return Math.max(0, Math.min(total - 1, f));
  };
  const pct = (f: number) => `${(100 * f) / Math.max(1, total - 1)}%`;
  const jump = (f: number) => {
    s.setPlaying(false);
    s.seek(Math.min(f, Math.max(0, s.received - 1)));
  };

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
      <canvas ref={plot} className="track__plot" data-testid="distance-plot" aria-label="Minimum distance between the people" />
      {!s.range && !marks.length && s.persons < 2 && (
        <span className="track__hint small">drag here to select frames for an edit</span>
      )}
      {s.range && (
        <div
          className="track__range"
          data-testid="track-range"
          style={{ left: pct(s.range[0]), width: `calc(${pct(s.range[1] - 1 - s.range[0])} + 2px)` }}
        />
      )}
      {marks.map((m) => (
        <button
          key={`${m.kind}-${m.start}`}
          className={`track__mark track__mark--${m.kind}`}
          data-testid={`mark-${m.kind}`}
          data-frame={m.start}
          style={{ left: pct(m.start), width: `max(6px, ${pct(m.end - 1 - m.start)})` }}
          title={`${m.kind} · frames ${m.start}–${m.end - 1}`}
          aria-label={`${m.kind} at frame ${m.start}`}
          onClick={() => jump(m.start)}
        />
      ))}
    </div>
  );
}
