// The three.js stage: renderer, soft lights with shadows, ground grid, the camera (CameraRig:
// orbit controls, preset views, following the people) and the people of the current motion —
// mannequins, or the skinned characters (Character.ts) once the motion's rig is there — with
// the marks where two people's bodies overlap (PenetrationMarks). Renders on demand (when
// something changed).
import * as THREE from "three";
import type { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { Skeleton } from "../api/types";
import type { FrameBuffer } from "../playback/frameBuffer";
import type { MotionRig } from "../playback/rig";
import type { CharacterMaker } from "../figure";
import type { Character } from "./Character";
import { CameraRig } from "./CameraRig";
import { footJoints, glowingContacts, glowStats } from "./contactGlow";
import type { ViewPreset } from "./framing";
import { Ground } from "./Ground";
import { FLOOR_COLOUR, LineGround } from "./LineGround";
import { Mannequin } from "./Mannequin";
import { PathOverlay } from "./PathOverlay";
import { PenetrationMarks } from "./PenetrationMarks";
import { QUALITY, type Quality, type QualitySettings } from "./quality";
import { debugFlags } from "./debugFlags";
import { setBodyAmbient } from "./bodyMaterial";
import { PALETTES, type StageTheme } from "./palette";

const BACKGROUND = PALETTES.dark.background;

/** The quality's body tessellation replaced by `?tess=` (debugFlags.ts), for profiling. */
function withTessellation(q: QualitySettings, tess: "old" | number[] | null): QualitySettings {
  if (tess === "old") return { ...q, weld: false, small: { ...q.small, radius: 0 } };
  if (!tess) return q;
  const [w, h, r, sw, sh, sr] = tess;
  return { ...q, sphere: [w, h], capsule: [q.capsule[0], r], small: { radius: q.small.radius || 0.055, radial: sr, sphere: [sw, sh] } };
}

export class Stage {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly rig: CameraRig;
  private readonly sun = new THREE.DirectionalLight("#ffffff", 2.2);
  private readonly hemi = new THREE.HemisphereLight("#dbe6ff", "#2b2f38", 1.4);
  private readonly ground: Ground | LineGround;
  private readonly settings: QualitySettings;
  private mannequins: Mannequin[] = [];
  /** Skinned characters, made on the first pose that has the maker and a rig of the motion on
   * stage; they stand in for the mannequins' bodies (the blob shadows stay the mannequins'). */
  private characters: Character[] = [];
  private figure: { make: CharacterMaker | null; rig: MotionRig | null } = { make: null, rig: null };
  /** What the last pose drew: the mannequins or the characters. */
  shown: "mannequin" | "character" = "mannequin";
  /** Per person: the joints of a pose blended between two frames (reused, no allocation). */
  private readonly blended: Float32Array[] = [];
  private highlights: { frame: number; version: number; buffer: FrameBuffer | null; sets: Set<number>[] } =
    { frame: -1, version: -1, buffer: null, sets: [] };
  /** The poses drawn, per person (the buffer's frame or the blend), for the penetration marks. */
  private readonly drawn: Float32Array[] = [];
  readonly penetration = new PenetrationMarks();
  private skeleton: Skeleton | null = null;
  private dirty = true;
  private readonly debug = debugFlags();
  readonly path = new PathOverlay();

  constructor(
    readonly canvas: HTMLCanvasElement,
    readonly quality: Quality = "full",
  ) {
    const settings = withTessellation(QUALITY[quality], this.debug.tess);
    this.settings = settings;
    // An opaque canvas (the scene always clears to its background), so the compositor need not
    // blend it with the page, and no drawing buffer kept between frames. three (r187) asks for
    // an alpha channel whatever its `alpha` option says, so the context is made here.
    const context = canvas.getContext("webgl2", {
      alpha: this.debug.alpha,
      depth: true,
      stencil: false,
      antialias: settings.antialias,
      premultipliedAlpha: true,
      preserveDrawingBuffer: false,
      powerPreference: "high-performance",
    });
    this.renderer = new THREE.WebGLRenderer({ canvas, context: context ?? undefined, antialias: settings.antialias });
    this.renderer.setPixelRatio(this.debug.pixelRatio ?? Math.min(window.devicePixelRatio, settings.maxPixelRatio));
    this.renderer.shadowMap.enabled = settings.shadowMap;
    this.renderer.shadowMap.type = THREE.PCFShadowMap;
    this.renderer.toneMapping = THREE.ACESFilmicToneMapping;
    this.scene.background = new THREE.Color(settings.gridLines ? FLOOR_COLOUR : BACKGROUND);
    this.ground = settings.gridLines ? new LineGround() : new Ground(BACKGROUND, settings.shadowMap);

    this.scene.add(this.hemi);
    this.sun.position.set(3, 7, 5);
    this.sun.castShadow = settings.shadowMap;
    this.sun.shadow.mapSize.set(2048, 2048);
    this.sun.shadow.radius = 4;
    this.sun.shadow.bias = -0.0005;
    Object.assign(this.sun.shadow.camera, { left: -6, right: 6, top: 6, bottom: -6, near: 0.5, far: 30 });
    this.scene.add(this.sun, this.sun.target);
    const fill = new THREE.DirectionalLight("#9fb4ff", 0.5);
    fill.position.set(-4, 3, -3);
    this.scene.add(fill);

    this.scene.add(this.ground.group, this.path.group, this.penetration.group);
    this.ground.group.visible = !this.debug.hide.has("ground");
    this.path.group.visible = !this.debug.hide.has("path");

    this.rig = new CameraRig(canvas, () => (this.dirty = true));
  }

  get camera(): THREE.PerspectiveCamera {
    return this.rig.camera;
  }

  get controls(): OrbitControls {
    return this.rig.controls;
  }

  /** While true the camera does not follow the people (the path tool). */
  set followPaused(on: boolean) {
    this.rig.followPaused = on;
  }

  /** Colours for the UI theme: background, floor grid and the floor's light bounce. */
  setTheme(theme: StageTheme): void {
    const p = PALETTES[theme];
    (this.scene.background as THREE.Color).set(this.settings.gridLines ? p.floor : p.background);
    this.ground.setPalette(p);
    this.hemi.color.set(p.sky);
    this.hemi.groundColor.set(p.bounce);
    setBodyAmbient(p.sky, p.bounce);
    this.dirty = true;
  }

  /** Look straight down on the people (for drawing a path), or back to the orbit view as it was. */
  setTopView(on: boolean): void {
    this.rig.setTopView(on);
    this.dirty = true;
  }

  get topView(): boolean {
    return this.rig.topView;
  }

  /** The pixel ratio drawn at (dynamic resolution changes it while playing). */
  get renderScale(): number {
    return this.renderer.getPixelRatio();
  }

  set renderScale(ratio: number) {
    const r = Math.min(ratio, window.devicePixelRatio || 1);
    if (r === this.renderer.getPixelRatio()) return;
    this.renderer.setPixelRatio(r); // resizes the drawing buffer, keeps the CSS size
    this.dirty = true;
  }

  resize(width: number, height: number): void {
    if (width <= 0 || height <= 0) return;
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  /** Replace the mannequins with one per person of `buffer`. */
  setPeople(skeleton: Skeleton, buffer: FrameBuffer): void {
    this.clearPeople();
    for (let p = 0; p < buffer.persons; p++) {
      const m = new Mannequin(skeleton, p, this.settings);
      m.group.visible = !this.debug.hide.has("people");
      // blob shadows: the mannequin's meshes that are not its body
      for (const c of m.group.children) if (!m.pickable.includes(c)) c.visible = !this.debug.hide.has("blobs");
      this.mannequins.push(m);
      this.scene.add(m.group);
    }
    this.skeleton = skeleton;
    this.applyView("default", buffer, 0);
  }

  clearPeople(): void {
    this.clearCharacters();
    if (!this.mannequins.length) return;
    this.mannequins.forEach((m) => m.dispose());
    this.mannequins = [];
    this.penetration.clear();
    this.dirty = true;
  }

  private clearCharacters(): void {
    this.characters.forEach((c) => c.dispose());
    this.characters = [];
    this.shown = "mannequin";
  }

  /** The character to draw instead of the mannequin: its maker and the rig of the motion on
   * stage (nulls: the mannequin). The people are drawn as characters while the rig matches the
   * buffer (its people and frames). True when this changed (pose again). */
  setFigure(make: CharacterMaker | null, rig: MotionRig | null): boolean {
    if (make === this.figure.make && rig === this.figure.rig) return false;
    this.clearCharacters();
    this.figure = { make, rig };
    this.dirty = true;
    return true;
  }

  /** The figure's rig when it is this buffer's motion, else null. */
  private rigOf(buffer: FrameBuffer): MotionRig | null {
    const { make, rig } = this.figure;
    if (!make || !rig || rig.people.length !== buffer.persons || rig.frames !== buffer.received || !this.mannequins.length) return null;
    if (!this.characters.length) {
      this.characters = rig.people.map((person, p) => {
        const c = make(this.mannequins[p].skeleton, p, person.offsets, this.settings);
        c.selected = this.mannequins[p].selected;
        c.hovered = this.mannequins[p].hovered;
        c.group.visible = !this.debug.hide.has("people");
        this.scene.add(c.group);
        return c;
      });
    }
    return rig;
  }

  /** How many characters are made (for the test hook). */
  get characterCount(): number {
    return this.characters.length;
  }

  get people(): number {
    return this.mannequins.length;
  }

  /** Meshes of every mannequin that a pointer ray can pick. */
  get pickable(): THREE.Object3D[] {
    if (this.shown === "character") return this.characters.flatMap((c) => c.pickable);
    return this.mannequins.flatMap((m) => m.pickable);
  }

  /** Joints to paint as selected / hovered, per person (applied at the next pose). */
  setSelection(selected: Set<number>[], hovered: Set<number>[]): void {
    this.mannequins.forEach((m, p) => {
      m.selected = selected[p] ?? new Set();
      m.hovered = hovered[p] ?? new Set();
    });
    this.characters.forEach((c, p) => {
      c.selected = this.mannequins[p]?.selected ?? new Set();
      c.hovered = this.mannequins[p]?.hovered ?? new Set();
    });
  }

  markDirty(): void {
    this.dirty = true;
  }

  /** Move the camera to a preset view of the people at frame t (CameraRig.applyView). */
  applyView(preset: ViewPreset, buffer: FrameBuffer, t: number): void {
    if (!this.skeleton || buffer.received === 0 || !this.mannequins.length) return;
    this.rig.applyView(preset, this.skeleton, buffer, t);
    this.moveLights(this.rig.centreAt(buffer, Math.min(t, buffer.received - 1), new THREE.Vector3()));
    this.dirty = true;
  }

  private moveLights(centre: THREE.Vector3): void {
    this.sun.position.set(centre.x + 3, 7, centre.z + 5);
    this.sun.target.position.set(centre.x, 0, centre.z);
    this.ground.centreOn(centre.x, centre.z);
  }

  /** Pose every mannequin at frame t of the buffer — blended by `weight` towards frame `next`
   * (playback between samples; highlights are frame t's) — and follow them with the camera. */
  pose(skeleton: Skeleton, buffer: FrameBuffer, t: number, next = t, weight = 0): void {
    const rig = this.rigOf(buffer);
    this.shown = rig ? "character" : "mannequin";
    this.mannequins.forEach((m, p) => {
      if (this.debug.hide.has("poses") && m.posed) return; // profiling: no vertex uploads
      let joints = buffer.frame(p, t);
      if (weight > 0 && next !== t) {
        const b = buffer.frame(p, next);
        const out = (this.blended[p] ??= new Float32Array(joints.length));
        for (let i = 0; i < joints.length; i++) out[i] = joints[i] + (b[i] - joints[i]) * weight;
        joints = out;
      }
      const contacts = this.contactsAt(buffer, t, p);
      // a character stands in: the mannequin only places its blob shadows
      m.bodyVisible = !rig;
      m.setPose(joints, contacts);
      if (rig) this.characters[p].setPose(rig.people[p], t, next, weight, contacts);
      this.drawn[p] = joints;
    });
    this.drawn.length = this.mannequins.length;
    // penetration where it happens: the overlaps of the poses drawn (the bodies keep their colours)
    this.penetration.update(skeleton, buffer, this.drawn);
    this.characters.forEach((c) => (c.group.visible = rig !== null && !this.debug.hide.has("people")));
    const centre = this.rig.follow(buffer, t, next, weight);
    if (centre) this.moveLights(centre);
    this.dirty = true;
  }

  /** The skeleton's foot joints (whose contacts are the floor's), for the skeleton they are of. */
  private feet: Set<number> = new Set();
  private feetOf: Skeleton | null = null;

  /** Person p's glowing contact joints at frame t, made once per frame (and buffer version),
   * not at every refresh that blends towards the next frame. */
  private contactsAt(buffer: FrameBuffer, t: number, p: number): Set<number> {
    const h = this.highlights;
    if (h.frame !== t || h.version !== buffer.version || h.buffer !== buffer) {
      this.highlights = { frame: t, version: buffer.version, buffer, sets: [] };
    }
    // only where a contact is asked (a hand on the other person) or new (a foot coming down):
    // feet planted on the floor no longer glow all the time (contactGlow.ts)
    if (this.skeleton && this.feetOf !== this.skeleton) this.feet = footJoints(this.skeleton.joints);
    this.feetOf = this.skeleton;
    if (!this.highlights.sets[p]) {
      this.highlights.sets[p] = glowingContacts(buffer.contacts, t, p, this.feet);
      glowStats.joints[p] = [...this.highlights.sets[p]];
      glowStats.joints.length = buffer.persons;
    }
    return this.highlights.sets[p];
  }

  /** Render if anything changed; true when a frame was drawn. */
  renderIfDirty(): boolean {
    if (!this.dirty) return false;
    this.renderer.render(this.scene, this.camera);
    this.dirty = false;
    return true;
  }

  dispose(): void {
    this.clearPeople();
    this.path.dispose();
    this.penetration.dispose();
    this.ground.dispose();
    this.rig.dispose();
    this.renderer.dispose();
  }
}
