import { expect, test } from "@playwright/test";
import { hook, motionOf, openStudio, shot, startGeneration, waitDone } from "./studio";

// "Person 2 reacts to Person 1": a one-person walk gets a reactor with an intent. While the react job streams
// the stage holds both people and the received frames grow; the result is stored as a new
// version (two people, person 0 the actor's stored joints, parent the actor) that undo/redo and
// its share link reach, with the pair's metrics and distance track.
test("Person 2 reacts to Person 1: the reactor streams in next to the walk and is stored as the next version", async ({ page }, info) => {
  await openStudio(page);
  await expect(page.getByTestId("reactor")).toHaveCount(0); // nothing to react to yet
  await startGeneration(page, "a person walks forward", 1, 8);
  const actor = await waitDone(page);
  expect(actor.persons).toBe(1);
  const actorId = actor.motionId!;

  await expect(page.getByTestId("reactor")).toBeVisible();
  await page.getByTestId("reactor-intent").fill("shake hands");
  // sample the studio as often as the page runs: the reactor's chunks arrive ~0.1 s apart
  await page.evaluate(() => {
    const w = window as unknown as { __samples: [string, number, number][] };
    w.__samples = [];
    let started = false; // the actor's own stream is "done" until the react job starts
    const id = setInterval(() => {
      const h = window.__interplay;
      started ||= h.phase === "connecting" || h.phase === "generating";
      if (!started) return;
      w.__samples.push([h.phase, h.persons, h.framesReceived]);
      if (h.phase === "done" || h.phase === "error") clearInterval(id);
    }, 1);
  });
  const posted = page.waitForRequest((r) => r.method() === "POST" && r.url().endsWith("/api/jobs"));
  await page.getByTestId("reactor-add").click();
  expect((await posted).postDataJSON()).toEqual({ mode: "react", actor_motion_id: actorId, prompt: "shake hands" });
  await page.waitForFunction(() => window.__interplay.phase === "generating" && window.__interplay.persons === 2);
  await shot(page, "r-reacting", info);
  const done = await waitDone(page);

  const samples = await page.evaluate(() => (window as unknown as { __samples: [string, number, number][] }).__samples);
  const live = samples.filter(([phase, persons, n]) => phase === "generating" && persons === 2 && n > 0);
  const counts = [...new Set(live.map(([, , n]) => n))];
  expect(counts.length, `frames seen while streaming: ${counts.join(", ")}`).toBeGreaterThan(1);
  expect(counts).toEqual([...counts].sort((a, b) => a - b)); // only ever grows
  expect(Math.min(...counts)).toBeLessThan(actor.frameCount);
  // the actor stayed on stage until the pair's first frames: never an empty stage
  expect(samples.every(([, persons, n]) => persons > 0 && n > 0)).toBe(true);

  // the result: a new version, two people, the actor unchanged, the actor as parent
  expect(done.persons).toBe(2);
  expect(done.framesReceived).toBe(actor.frameCount);
  const pairId = done.motionId!;
  expect(pairId).not.toBe(actorId);
  await expect(page).toHaveURL(new RegExp(`/m/${pairId}$`));
  const [stored, parent] = [await motionOf(page, pairId), await motionOf(page, actorId)];
  expect(stored.parent_id).toBe(actorId);
  expect(stored.people).toHaveLength(2);
  const a = parent.people[0].joints.flat(2);
  const b = stored.people[0].joints.flat(2);
  expect(b).toHaveLength(a.length);
  expect(Math.max(...a.map((x, i) => Math.abs(x - b[i])))).toBeLessThan(1e-4);
  expect(stored.people[1].joints).toHaveLength(actor.frameCount);
  expect(stored.highlights?.min_distance).toHaveLength(actor.frameCount);

  // the studio shows it like any two-person motion
  await expect(page.getByTestId("progress")).toHaveCount(0);
  await expect(page.getByTestId("reactor")).toHaveCount(0); // B already there
  await expect(page.getByTestId("metric-intersection_frequency")).toBeVisible();
  await expect(page.getByTestId("distance-plot")).toBeVisible();
  await expect(page.getByTestId("version-edit")).toContainText("Person 2 reacts to Person 1: shake hands");
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
  await page.waitForTimeout(1500); // let the pair play a little for the picture
  await shot(page, "r-reacted", info);

  // undo goes back to the actor alone, redo to the pair
  await page.getByTestId("undo").click();
  await page.waitForFunction((id) => window.__interplay.motionId === id && window.__interplay.persons === 1, actorId);
  await expect(page.getByTestId("reactor")).toBeVisible();
  await page.getByTestId("redo").click();
  await page.waitForFunction((id) => window.__interplay.motionId === id && window.__interplay.persons === 2, pairId);

  // the share link reopens the pair
  await page.goto(`/m/${pairId}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  const reopened = await hook(page);
  expect([reopened.motionId, reopened.persons]).toEqual([pairId, 2]);
  await expect(page.getByTestId("version-label")).toHaveText("v2 / 2");
});

// Cancel from the reactor's progress state: the server runs one job at a time, so long jobs sent
// through the API first keep the react job queued while Cancel is pressed (one 20 s job takes
// only ~1.6 s on a quiet machine, so six are queued: ~10 s of queue, more under load). The studio goes back
// to the actor as it was (one person, its id and URL, the reactor panel), nothing is stored.
// Every wait is on a state of the app (the test hook's job id and stream mode, the API's job
// status, Playwright's retrying expects), never on time: the react job is shown to be queued
// behind the blocker before the UI is checked, so the panel's state cannot move under the checks.
test("Cancel while B is reacting goes back to the actor alone", async ({ page }, info) => {
  await openStudio(page);
  await startGeneration(page, "a person walks forward", 1, 2);
  const actorId = (await waitDone(page)).motionId!;
  const blockers: string[] = [];
  for (let i = 0; i < 6; i++) {
    const res = await page.request.post("/api/jobs", {
      data: { prompt: "a person walks forward, then jumps, then dances, then sits down", persons: 1, seconds: 20, seed: i },
    });
    expect(res.status()).toBe(201);
    blockers.push((await res.json()).job_id);
  }

  await expect(page.getByTestId("reactor-add")).toBeEnabled(); // the panel rendered for the actor
  const posted = page.waitForResponse((r) => r.request().method() === "POST" && r.url().endsWith("/api/jobs"));
  await page.getByTestId("reactor-add").click(); // no intent: the field is left out
  expect((await posted).request().postDataJSON()).toEqual({ mode: "react", actor_motion_id: actorId });
  // the page streams the react job, which waits in the server's queue behind the blocker
  await page.waitForFunction(() => window.__interplay.streamMode === "react" && window.__interplay.jobId !== null);
  const jobId = await page.evaluate(() => window.__interplay.jobId!);
  expect((await (await page.request.get(`/api/jobs/${jobId}`)).json()).status).toBe("queued");
  await expect(page.getByTestId("progress")).toContainText("Starting the reactor");
  await expect(page.getByTestId("reactor-add")).toBeDisabled();
  await expect(page.getByTestId("reactor-add")).toHaveText("Reacting…");

  const deleted = page.waitForResponse((r) => r.request().method() === "DELETE" && r.url().endsWith(`/api/jobs/${jobId}`));
  await page.getByTestId("cancel").click();
  expect(await (await deleted).json()).toMatchObject({ cancelled: true });

  await page.waitForFunction((id) => window.__interplay.motionId === id && window.__interplay.phase === "done", actorId, { timeout: 60_000 });
  const h = await hook(page);
  expect(h.persons).toBe(1);
  await expect(page).toHaveURL(new RegExp(`/m/${actorId}$`));
  await expect(page.getByTestId("progress")).toHaveCount(0);
  await expect(page.getByTestId("error-banner")).toBeHidden();
  await expect(page.getByTestId("reactor-add")).toBeEnabled();
  await expect(page.getByTestId("version-label")).toHaveText("v1 / 1");
  await shot(page, "r-cancelled", info);
  const job = await (await page.request.get(`/api/jobs/${jobId}`)).json();
  expect(job.status).toBe("cancelled");
  expect((await page.request.get(`/api/motions/${job.motion_id}`)).status()).toBe(409);
  for (const id of blockers) await page.request.delete(`/api/jobs/${id}`); // free the server
});
