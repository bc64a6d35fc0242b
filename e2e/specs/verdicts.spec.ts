// Verdicts read honestly (issue 26.4): a correction the reviewer kept without raising the score
// is "rejected: the score did not improve", never "✓ accepted (0.26 → 0.26)", and is not named
// as a fix; `failed` and `not_covered` verdicts are shown as such, with what was shown instead.
import { expect, test, type APIRequestContext } from "@playwright/test";
import { makeMotion, openStudio, shot } from "./studio";

const PROMPT = "a person walks forward, then jumps, then sits down";

interface Round { round: number; verdict: string; summary?: string; score: number; instructions: unknown[]; captions: Record<string, string> }
interface Corr { round: number; accepted: boolean; score_before: number; score_after: number | null }
interface Stored {
  id: string;
  plan: { segments: Record<string, unknown>[] };
  review: { segments: { segment: number; reviews: Round[]; corrections: Corr[] }[] };
}

/** A kept correction that did not raise the score and whose round's review did not pass. */
const flatKept = (m: Stored) =>
  m.review.segments.find((s) =>
    s.corrections.some((c) => c.accepted && c.score_after !== null && c.score_after <= c.score_before && s.reviews.find((r) => r.round === c.round)?.verdict !== "ok"),
  );

async function findFlat(request: APIRequestContext): Promise<[Stored, number]> {
  for (let seed = 1; seed <= 40; seed++) {
    const m: Stored = await (await request.get(`/api/motions/${await makeMotion(request, { prompt: PROMPT, seconds: 6, seed })}`)).json();
    const s = flatKept(m);
    if (s) return [m, s.segment];
  }
  throw new Error("no seed in 1…40 keeps a correction that does not raise the score");
}

test("a kept correction that did not raise the score reads rejected, and is no fix", async ({ page, request }, info) => {
  const [m, i] = await findFlat(request);
  await openStudio(page, `/m/${m.id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  const card = page.getByTestId(`segment-${i}`);
  await expect(card.getByTestId("correction").filter({ hasText: /^✗ rejected: the score did not improve \(score -?\d\.\d+ → -?\d\.\d+\)$/ }).first()).toBeVisible();
  // nowhere "accepted" with the same score before and after
  for (const text of await page.getByTestId("plan").getByTestId("correction").allTextContents()) {
    const same = text.match(/^✓ accepted \(score (-?[\d.]+) → (-?[\d.]+)\)$/);
    if (same) expect(same[1], text).not.toBe(same[2]);
  }
  await expect(card.getByTestId(`segment-verdict-${i}`)).not.toContainText("corrected:");
  await card.scrollIntoViewIfNeeded();
  await shot(page, "v-flat-rejected", info);
});

test("failed and not_covered verdicts are shown as such, with what was shown", async ({ page, request }, info) => {
  const m: Stored = await (await request.get(`/api/motions/${await makeMotion(request, { prompt: PROMPT, seconds: 6, seed: 5 })}`)).json();
  // the reviewer's newer verdicts, as the backend sends them: segment 0 failed after its rounds,
  // segment 2 not in the library (its plan segment's coverage says what was shown)
  const body = structuredClone(m);
  const s0 = body.review.segments.find((s) => s.segment === 0)!;
  const last = s0.reviews[s0.reviews.length - 1];
  s0.reviews.push({ ...last, round: last.round + 1, verdict: "failed", summary: "the person stands still",
    instructions: [{ kind: "regenerate", prompt: "a person walks forward", reason: "the captions ('the person stands still') hardly agree with 'a person walks forward'" }] });
  const s2 = body.review.segments.find((s) => s.segment === 2)!;
  s2.reviews = [{ ...s2.reviews[0], round: 0, verdict: "not_covered", instructions: [] }];
  s2.corrections = [];
  body.plan.segments[2].coverage = { how: "nearest", similarity: 0.41, shown: "a person squats down" };
  await page.route(`**/api/motions/${m.id}`, (route) => route.fulfill({ json: body }));
  await openStudio(page, `/m/${m.id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await expect(page.getByTestId("segment-verdict-0")).toHaveText("failed: the motion hardly matches “a person walks forward” (it shows “the person stands still”)");
  await expect(page.getByTestId("segment-0").locator(".badge--failed").first()).toHaveText("failed");
  await expect(page.getByTestId("segment-verdict-2")).toHaveText("not in the library — showing the nearest: a person squats down");
  await expect(page.getByTestId("segment-2").locator(".badge--not-covered")).toHaveText("not in the library");
  await expect(page.getByTestId("plan")).not.toContainText(/\bnot_covered\b|\bcorrect\b/);
  await page.getByTestId("segment-2").scrollIntoViewIfNeeded();
  await shot(page, "v-not-covered", info);
});
