// Issue 26, point 8: feet on the floor always glowed green, drowning the contact cue. Now a
// contact glows only where it is asked — a hand on the other person — or new — a foot that came
// down within the last 6 frames (scene/contactGlow.ts); the stream still lists every contact.
import { expect, test, type Page } from "@playwright/test";
import { makeMotion, openStudio, shot, showFrame } from "./studio";

const FEET = [7, 8, 10, 11]; // left/right ankle, left/right foot (SMPL)
const WRISTS = [20, 21];

type Contacts = [number, number][][];

async function contactsOf(page: Page, id: string): Promise<Contacts> {
  const m = await (await page.request.get(`/api/motions/${id}`)).json();
  return m.highlights.contacts as Contacts;
}

const glowing = (page: Page) => page.evaluate(() => window.__interplay.glowing);
const has = (c: [number, number][] | undefined, p: number, j: number) => (c ?? []).some(([q, k]) => q === p && k === j);

test("feet glow only when they come down; a hand on the other person glows while it touches", async ({ page }, info) => {
  const walk = await makeMotion(page.request, { prompt: "a person walks forward", persons: 1, seconds: 4, seed: 2 });
  const contacts = await contactsOf(page, walk);
  // a foot coming down after the first frame, and a frame where it has been down 8 frames
  let landing: { t: number; j: number } | null = null;
  for (let t = 1; t < contacts.length - 9 && !landing; t++) {
    for (const j of FEET) {
      const down = [0, 1, 2, 3, 4, 5, 6, 7, 8].every((k) => has(contacts[t + k], 0, j));
      if (down && !has(contacts[t - 1], 0, j)) landing = { t, j };
    }
  }
  expect(landing, "the walk has a foot coming down").not.toBeNull();
  const planted = contacts.findIndex((c) => c.some(([, j]) => FEET.includes(j)));
  expect(planted).toBe(0); // a foot is on the floor from the first frame: the stream lists it

  await openStudio(page, `/m/${walk}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  // frame 0: feet on the floor since the start — listed, not glowing
  await showFrame(page, 0);
  expect(await glowing(page)).toEqual([[]]);
  await shot(page, "cg-standing-no-glow", info);
  // the landing: that foot glows, for a few frames only
  await showFrame(page, landing!.t);
  expect((await glowing(page))[0]).toContain(landing!.j);
  await shot(page, "cg-foot-lands", info);
  await showFrame(page, landing!.t + 8);
  expect(has(contacts[landing!.t + 8], 0, landing!.j)).toBe(true);
  expect((await glowing(page))[0]).not.toContain(landing!.j);

  // two people shake hands: a hand on the other person glows while it touches
  const pair = await makeMotion(page.request, { prompt: "two people shake hands", persons: 2, seconds: 4, seed: 3 });
  const pc = await contactsOf(page, pair);
  const touch = pc.findIndex((c, t) => t > 10 && c.some(([, j]) => WRISTS.includes(j)));
  expect(touch, "the handshake touches").toBeGreaterThan(0);
  const [p, j] = pc[touch].find(([, k]) => WRISTS.includes(k))!;
  await openStudio(page, `/m/${pair}`);
  await page.waitForFunction(() => window.__interplay.phase === "done" && window.__interplay.persons === 2);
  await showFrame(page, touch + 5 < pc.length && has(pc[touch + 5], p, j) ? touch + 5 : touch);
  const lit = await glowing(page);
  expect(lit[p]).toContain(j);
  // and the feet standing since the start stay dark
  const standing = FEET.filter((f) => pc.slice(0, touch + 6).every((c) => has(c, p, f)));
  for (const f of standing) expect(lit[p]).not.toContain(f);
  await shot(page, "cg-handshake", info);
});
