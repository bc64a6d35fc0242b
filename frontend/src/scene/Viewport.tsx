// Hosts the three.js Stage and runs the render loop: advances the playback clock, poses the
// mannequins from the FrameBuffer (while playing, blended between the 20 fps frames, so each
// display refresh gets a new pose) and renders when something changed. No per-frame React state
// except the integer frame number the timeline shows. Takes the preset views the UI asks for
// (views.ts) and reports the camera and the penetration marks back there.
import { useEffect, useRef } from "react";
import { advance, blendAt } from "../playback/timeline";
import { FPS, frames, playhead, renderStats, useStudio } from "../store";
import { jointsOfPart } from "../directing/parts";
import { shownPath, useFollowed } from "../directing/followed";
import { Vector3 } from "three";
import { pointer, sceneProbe } from "../store";
import { Picker } from "./Picker";
import { attachPointer } from "./interaction";
import { detectQuality, QUALITY } from "./quality";
import { debugFlags } from "./debugFlags";
import { LIGHT_RESOLUTION, ResolutionController } from "./resolution";
import { Stage } from "./Stage";
import { figureData, figureStats, useFigure, watchFigure } from "../figure";
import { viewRequest, viewStats } from "./views";

export function Viewport() {
  const canvasRef = useRef<HTMLCanvasElement>(null);

  useEffect(() => {
    const canvas = canvasRef.current;
    if (!canvas) return;
    const stage = new Stage(canvas, detectQuality());
    renderStats.quality = stage.quality;
    // light quality: hold the display's rate with the render scale, judged on frames drawn at
    // consecutive refreshes (playback), from their requestAnimationFrame times
    const dynres = QUALITY[stage.quality].dynamicResolution && debugFlags().dynamicResolution
      ? new ResolutionController(LIGHT_RESOLUTION)
      : null;
    if (dynres) stage.renderScale = dynres.scale;
    renderStats.scale = stage.renderScale;
    let drewLast = false;
    let resized = false; // since the view was last fitted
    const fit = () => {
      stage.resize(canvas.clientWidth, canvas.clientHeight);
      resized = true;
      const scale = dynres?.fit(canvas.clientWidth * canvas.clientHeight);
      if (scale) renderStats.scale = stage.renderScale = scale;
    };
    const observer = new ResizeObserver(fit);
    observer.observe(canvas);
    fit();

    const detach = attachPointer(stage, canvas);
    sceneProbe.project = (x, y, z) => {
      const v = new Vector3(x, y, z).project(stage.camera);
      const r = canvas.getBoundingClientRect();
      return [r.left + ((v.x + 1) / 2) * r.width, r.top + ((1 - v.y) / 2) * r.height];
    };
    const picker = new Picker(canvas, stage.camera);
    sceneProbe.ground = (cx, cy) => picker.ground(cx, cy);
    let overlay = { pointer: -1, path: null as unknown, tool: "", selected: null as unknown, gen: -1, followed: null as unknown, motion: null as string | null, versions: null as unknown };
    let look = { theme: "", top: false };
    let generation = -1; // which FrameBuffer contents the mannequins were built for
    let framed = -1; // the buffer's version the view was last fitted to
    let drawn = { pos: -1, version: -1 };
    let last = performance.now();
    let raf = 0;

    const tick = (now: number) => {
      raf = requestAnimationFrame(tick);
      const interval = now - last;
      const dt = Math.min(0.1, interval / 1000);
      last = now;
      const s = useStudio.getState();
      const skeleton = s.skeleton;

      if (frames.generation !== generation) {
        stage.clearPeople();
        if (skeleton && frames.received > 0) {
          stage.setPeople(skeleton, frames);
          generation = frames.generation;
          framed = frames.version;
          resized = false;
          drawn = { pos: -1, version: -1 };
        }
      }
      if (stage.people > 0) {
        // a preset asked for; or, while the user has not moved the camera, the same view fitted
        // again to a motion all in whose frames changed since (the first chunk of a stream
        // opened it; a job may send its frames again, corrected, before it is done), or to a
        // resized canvas
        const refit = frames.received === frames.total && (framed !== frames.version || resized);
        const preset = viewRequest.preset ?? (refit && !stage.rig.moved && s.tool !== "path" ? stage.rig.view : null);
        viewRequest.preset = null;
        if (preset && s.tool !== "path") {
          stage.applyView(preset, frames, s.frame);
          framed = frames.version;
          resized = false;
          drawn = { pos: -1, version: -1 };
        }
      }
      // the skinned character, once the motion on stage is stored and its rig has come
      const rig = useFigure.getState().figure === "character" && s.stream.phase === "done" &&
        figureData.rig?.motionId === s.motionId ? figureData.rig : null;
      if (stage.setFigure(rig && figureData.make, rig)) drawn = { pos: -1, version: -1 };
      stage.controls.enabled = s.tool !== "path";
      // drawing: the floor must stay put under the pointer (no following the people)
      stage.followPaused = s.tool === "path";
      if (look.theme !== s.theme) stage.setTheme(s.theme);
      const top = s.topView && s.tool === "path";
      if (look.top !== top) stage.setTopView(top);
      look = { theme: s.theme, top };
      const followed = useFollowed.getState();
      if (overlay.pointer !== pointer.version || overlay.path !== s.path || overlay.tool !== s.tool ||
        overlay.selected !== s.selected || overlay.gen !== generation || overlay.followed !== followed ||
        overlay.motion !== s.motionId || overlay.versions !== s.versions) {
        // the path drawn or waiting for the next Generate, else the one the motion followed
        const shown = shownPath(s.path, followed.path, followed.show, s.motionId, s.versions.ids);
        const points = pointer.drawing ?? shown.points;
        // handles on presets and short drawn paths (a long stroke would be a string of beads)
        const editable = s.tool === "path" && !pointer.drawing && !shown.followed && (s.path.preset !== null || points.length <= 12);
        stage.path.update(points, pointer.drawing ? s.path.person : shown.person, editable);
        if (skeleton) {
          const sets = (sel: { person: number; part: Parameters<typeof jointsOfPart>[1] } | null) =>
            [0, 1].map((p) => new Set(sel && sel.person === p ? jointsOfPart(skeleton.joints, sel.part) : []));
          stage.setSelection(sets(s.selected), sets(s.tool === "part" ? pointer.hover : null));
        }
        overlay = { pointer: pointer.version, path: s.path, tool: s.tool, selected: s.selected, gen: generation, followed, motion: s.motionId, versions: s.versions };
        drawn = { pos: -1, version: -1 };
        stage.markDirty();
      }
      if (stage.people > 0 && skeleton) {
        const clock = advance({ pos: playhead.pos, playing: s.playing }, dt, {
          fps: FPS,
          speed: s.speed,
          loop: s.loop,
          available: frames.received,
          total: frames.total,
        });
        playhead.pos = clock.pos;
        // playing: every refresh draws the pose between the two frames around the clock;
        // paused: exactly the frame shown (what the timeline and the test hook name)
        const blend = blendAt(clock.pos, frames.received);
        const f = blend.frame;
        const pos = clock.playing ? f + blend.weight : f;
        if (clock.playing !== s.playing) s.setPlaying(clock.playing);
        if (f !== s.frame) useStudio.setState({ frame: f });
        if (pos !== drawn.pos || frames.version !== drawn.version) {
          stage.pose(skeleton, frames, f, blend.next, clock.playing ? blend.weight : 0);
          drawn = { pos, version: frames.version };
        }
      }
      const drew = stage.renderIfDirty();
      if (drew) renderStats.renders++;
      if (dynres && drew && drewLast) {
        const scale = dynres.sample(interval);
        if (scale !== null) renderStats.scale = stage.renderScale = scale;
      }
      drewLast = drew;
      if (drew) {
        stage.camera.position.toArray(viewStats.position);
        stage.controls.target.toArray(viewStats.target);
      }
      viewStats.view = stage.rig.view;
      viewStats.moved = stage.rig.moved;
      viewStats.markCount = stage.penetration.marks.count;
      viewStats.marks = stage.penetration.marks.data;
      figureStats.shown = stage.shown;
      figureStats.characters = stage.characterCount;
    };
    raf = requestAnimationFrame(tick);
    const unwatchFigure = watchFigure();
    return () => {
      unwatchFigure();
      cancelAnimationFrame(raf);
      detach();
      sceneProbe.project = sceneProbe.ground = null;
      observer.disconnect();
      stage.dispose();
    };
  }, []);

  return <canvas ref={canvasRef} className="viewport-canvas" data-testid="viewport" />;
}
