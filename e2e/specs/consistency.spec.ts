// One naming of people (Person 1 / Person 2 on the page, person1 / person2 in file names), the
// HTML 404 page for bad paths, the page's limits from the API's schema, and the seed field.
import { expect, test } from "@playwright/test";
import { openStudio, shot } from "./studio";

test("bad paths get an HTML 404 page that leads back to the studio; /api keeps JSON", async ({ page }, info) => {
  for (const path of ["/m/", "/m/abc/def", "/nothing/here"]) {
    const res = await page.goto(path);
    expect(res!.status(), path).toBe(404);
    expect(res!.headers()["content-type"], path).toContain("text/html");
    await expect(page.getByTestId("not-found")).toContainText("This page does not exist");
  }
  await shot(page, "c-not-found", info);
  await page.getByRole("link", { name: "Open the Interplay studio" }).click();
  await expect(page.getByTestId("prompt")).toBeVisible();
  const api = await page.request.get("/api/nothing");
  expect(api.status()).toBe(404);
  expect((await api.json()).detail).toBeTruthy();
});

test("the page's limits are the API's (read from /openapi.json)", async ({ page }) => {
  const schema = await (await page.request.get("/openapi.json")).json();
  const job = schema.components.schemas.JobCreate.properties;
  const maxLength = job.prompt.maxLength ?? job.prompt.anyOf?.find((b: { maxLength?: number }) => b.maxLength)?.maxLength;
  expect(maxLength).toBe(500);
  await openStudio(page);
  // the limit is the counter's (a longer prompt is kept as typed and said to be too long, not cut)
  await expect(page.getByTestId("prompt-count")).toHaveAttribute("data-max", String(maxLength));
  await expect(page.getByTestId("seconds")).toHaveAttribute("min", String(job.seconds.minimum));
  await expect(page.getByTestId("seconds")).toHaveAttribute("max", String(job.seconds.maximum));
  const seedMax = job.seed.anyOf.find((b: { maximum?: number }) => b.maximum !== undefined).maximum;
  await expect(page.getByTestId("seed")).toHaveAttribute("max", String(seedMax));
  // a longer prompt is kept as typed (never cut silently) and said to be over the API's limit
  await page.getByTestId("prompt").fill("a".repeat(600));
  expect((await page.getByTestId("prompt").inputValue()).length).toBe(600);
  await expect(page.getByTestId("prompt-count")).toHaveText(`600 / ${maxLength}`);
  await expect(page.getByTestId("form-problems")).toContainText(`the limit is ${maxLength}`);
});

test("the seed field: a typed seed is sent, New seed picks one, empty sends none", async ({ page }) => {
  await openStudio(page);
  await page.getByTestId("prompt").fill("a person waves");
  await page.getByTestId("seconds").fill("1");
  const body = async () => {
    const sent = page.waitForRequest((r) => r.url().endsWith("/api/jobs") && r.method() === "POST");
    await page.getByTestId("generate").click();
    const b = (await sent).postDataJSON();
    await page.waitForFunction(() => ["done", "error"].includes(window.__interplay.phase), null, { timeout: 120_000 });
    return b;
  };
  await page.getByTestId("seed").fill("1234");
  expect((await body()).seed).toBe(1234);
  await expect(page.getByTestId("plan-meta")).toContainText("seed 1234");
  await page.getByTestId("new-seed").click();
  const picked = Number(await page.getByTestId("seed").inputValue());
  expect(Number.isInteger(picked) && picked >= 0).toBe(true);
  await page.getByTestId("prompt").fill("a person waves twice");
  expect((await body()).seed).toBe(picked);
  await page.getByTestId("seed").fill("");
  await page.getByTestId("prompt").fill("a person waves again");
  expect((await body()).seed).toBeUndefined();
});

test("people are Person 1 and Person 2 on the page, person1 and person2 in file names", async ({ page, request }, info) => {
  const res = await request.post("/api/jobs", { data: { prompt: "two people shake hands", persons: 2, seconds: 2, seed: 3 } });
  const { motion_id } = await res.json();
  await expect.poll(async () => (await request.get(`/api/motions/${motion_id}`)).status(), { timeout: 120_000 }).toBe(200);
  await openStudio(page, `/m/${motion_id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect(page.getByTestId("legend")).toContainText("Person 1");
  await expect(page.getByTestId("legend")).toContainText("Person 2");
  await expect(page.getByTestId("export-bvh-0")).toHaveText("BVH · Person 1");
  await expect(page.getByTestId("export-bvh-1")).toHaveText("BVH · Person 2");
  const one = page.waitForEvent("download");
  await page.getByTestId("export-bvh-1").click();
  expect((await one).suggestedFilename()).toBe(`interplay-two-people-shake-hands-${motion_id}-person2.bvh`);
  const names: string[] = [];
  page.on("download", (d) => names.push(d.suggestedFilename()));
  await page.getByTestId("export-bvh-both").click();
  const named = `interplay-two-people-shake-hands-${motion_id}`;
  await expect.poll(() => names.sort()).toEqual([`${named}-person1.bvh`, `${named}-person2.bvh`]);
  await page.getByTestId("tool-path").click();
  await expect(page.getByTestId("path-person-0")).toHaveText("Person 1");
  await expect(page.getByTestId("path-person-1")).toHaveText("Person 2");
  await expect(page.locator("body")).not.toContainText(/\bperson [AB]\b|\bperson[01]\b/i);
  await shot(page, "c-naming", info);
});
