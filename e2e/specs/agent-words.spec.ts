// The agent panel in words: a corrected segment says what was corrected, each instruction says
// what became of it (accepted / rejected and why), a failed one says why — never the reviewer's
// raw verdict "correct" (which means "needs correction").
import { expect, test, type APIRequestContext } from "@playwright/test";
import { makeMotion, openStudio, shot, waitDone } from "./studio";

interface Stored {
  id: string;
  seed: number;
  review: { segments: { segment: number; reviews: { verdict: string }[]; corrections: { accepted: boolean; score_after: number | null }[] }[] } | null;
}

async function stored(request: APIRequestContext, body: Record<string, unknown>): Promise<Stored> {
  return (await request.get(`/api/motions/${await makeMotion(request, body)}`)).json();
}

/** The first seed of 1…24 where one of the prompt's segments reads as wanted; that segment. */
async function findSeed(request: APIRequestContext, prompt: string, want: (s: Seg) => boolean): Promise<[Stored, number]> {
  for (let seed = 1; seed <= 24; seed++) {
    const m = await stored(request, { prompt, seconds: SECONDS, seed });
    const s = m.review?.segments.find(want);
    if (s) return [m, s.segment];
  }
  throw new Error(`no seed in 1…24 gives the wanted review for "${prompt}"`);
}

type Seg = NonNullable<Stored["review"]>["segments"][number];
// The calibrated judge (issue 24) re-draws what does not match its words: a three-segment walk,
// jump and sit has segments it corrects and segments it cannot fix
const PROMPT = "a person walks forward, then jumps, then sits down";
const SECONDS = 6;
const corrected = (s: Seg) => s.reviews[s.reviews.length - 1].verdict === "ok" && s.corrections.some((c) => c.accepted);
const failed = (s: Seg) =>
  ["correct", "failed"].includes(s.reviews[s.reviews.length - 1].verdict) && s.corrections.some((c) => !c.accepted && c.score_after !== null);

test("a corrected segment's outcome is shown in words, live and from the stored review", async ({ page, request }, info) => {
  const prompt = PROMPT;
  const [m, i] = await findSeed(request, prompt, corrected);
  info.annotations.push({ type: "seed", description: `${prompt}: seed ${m.seed} is corrected` });

  // live: the same prompt and seed through the page's seed field streams the same review
  await openStudio(page);
  await page.getByTestId("prompt").fill(prompt);
  await page.getByTestId("seconds").fill(String(SECONDS));
  await page.getByTestId("seed").fill(String(m.seed));
  await page.getByTestId("generate").click();
  const done = await waitDone(page);
  const verdict = page.getByTestId(`segment-verdict-${i}`);
  await expect(verdict).toHaveText(/^corrected: .*(redrawn|edited|re-generated)/);
  const panel = page.getByTestId("plan");
  await expect(panel.getByTestId("correction").filter({ hasText: /^✓ accepted \(score -?\d\.\d+ → -?\d\.\d+\)$/ }).first()).toBeVisible();
  await expect(panel.getByTestId("instruction").first()).toContainText("why:");
  await expect(panel).toContainText("needs correction"); // the first round's badge, in words
  await expect(panel).not.toContainText(/\bcorrect\b/); // never the bare word "correct"
  await expect(panel).toContainText("passed"); // the round after the correction
  await expect(page.getByTestId("plan-meta")).toContainText(`seed ${m.seed}`);
  const live = await verdict.textContent();
  await shot(page.getByTestId("plan"), "w-agent-corrected", info);

  // the stored review reads the same after a reload
  await page.goto(`/m/${done.motionId}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect(page.getByTestId(`segment-verdict-${i}`)).toHaveText(live!);
});

test("a segment the corrections could not fix says failed and why; a rejected correction says why", async ({ page, request }, info) => {
  const [m, i] = await findSeed(request, PROMPT, failed);
  await openStudio(page, `/m/${m.id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect(page.getByTestId(`segment-verdict-${i}`)).toHaveText(/^failed: /);
  const outcome = page.getByTestId(`segment-${i}`).getByTestId("correction").filter({ hasText: /rejected/ }).first();
  await expect(outcome).toHaveText(/^✗ rejected: (the score dropped|the score did not improve|it made .+ worse|it misses .+) \(score -?\d\.\d+ → -?\d\.\d+\)$/);
  await expect(page.getByTestId("plan")).not.toContainText(/\bcorrect\b/);
  await shot(page.getByTestId("plan"), "w-agent-failed", info);
});
