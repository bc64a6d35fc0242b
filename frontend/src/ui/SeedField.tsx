import { useStudio } from "../store";

/** A random seed in [0, max]. */
export function randomSeed(max: number, random: () => number = Math.random): number {
  return Math.floor(random() * (max + 1));
}

/** The seed field text → the seed to send: null (random) when empty or not a whole number in
 * [0, max]. */
export function parseSeed(text: string, max: number): number | null {
  const t = text.trim();
  if (!/^\d+$/.test(t)) return null;
  const n = Number(t);
  return Number.isSafeInteger(n) && n <= max ? n : null;
}

/** The prompt bar's seed: empty means a random one (the motion's plan says which it used);
 * "New seed" fills in a fresh random one; the same prompt and seed make the same motion. */
export function SeedField() {
  const seed = useStudio((s) => s.seed);
  const setSeed = useStudio((s) => s.setSeed);
  const max = useStudio((s) => s.limits.seedMax);
  return (
    <span className="seed" role="group" aria-label="Seed">
      <input
        type="number"
        className="seed__input"
        data-testid="seed"
        aria-label="Seed (empty: random)"
        title="Seed: the same prompt and seed make the same motion; empty for a random one"
        placeholder="seed"
        min={0}
        max={max}
        step={1}
        value={seed ?? ""}
        onChange={(e) => setSeed(parseSeed(e.target.value, max))}
      />
      <button
        type="button"
        className="icon-button"
        data-testid="new-seed"
        aria-label="New seed"
        title="New seed: a fresh random one"
        onClick={() => setSeed(randomSeed(max))}
      >
        ⚄
      </button>
    </span>
  );
}
