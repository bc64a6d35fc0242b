export function chromiumCpu(root?: number, threads?: boolean): Record<string, number>;
export function perFrame(
  before: Record<string, number>,
  after: Record<string, number>,
  frames: number,
): { total: number; per: Record<string, number> };
