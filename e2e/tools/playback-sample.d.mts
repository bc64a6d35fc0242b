export function samplePlayback(ms: number): Promise<{
  dt: number;
  renders: number;
  raf: number;
  scale: number | null;
  intervalMs: { p50: number; p95: number; p99: number };
  missed: number;
}>;
