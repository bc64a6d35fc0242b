// The request limits the page enforces (prompt length, seconds, people, seed, path size), read from the
// API's own schema (/openapi.json: `JobCreate` and `TrajectoryIn`, made from
// backend/interplay/pipeline/requests.py) instead of being written twice. The defaults are
// used only until the schema arrives, or if it cannot be read.

export interface Limits {
  promptMax: number;
  secondsMin: number;
  secondsMax: number;
  seedMax: number;
  /** How many people a request may have: 1 … personsMax (the schema's `persons` enum). */
  personsMax: number;
  /** Points of a drawn path. */
  pathPoints: number;
  /** Metres from the origin of any drawn point. */
  pathCoord: number;
}

export const DEFAULT_LIMITS: Limits = {
  promptMax: 500,
  secondsMin: 1,
  secondsMax: 20,
  seedMax: 2 ** 31 - 1,
  personsMax: 2,
  pathPoints: 2000,
  pathCoord: 100,
};

type Schema = Record<string, unknown>;

const isObj = (x: unknown): x is Schema => typeof x === "object" && x !== null && !Array.isArray(x);

/** `key` of a property schema, or of one of its `anyOf` branches (an optional field is
 * `anyOf: [{type, …limits}, {type: "null"}]`). */
function constraint(prop: unknown, key: string): number | undefined {
  if (!isObj(prop)) return undefined;
  if (typeof prop[key] === "number") return prop[key] as number;
  for (const branch of Array.isArray(prop.anyOf) ? prop.anyOf : []) {
    const v = constraint(branch, key);
    if (v !== undefined) return v;
  }
  return undefined;
}

/** The largest number of an `enum` (persons: [1, 2]). */
function enumMax(prop: unknown): number | undefined {
  const values = isObj(prop) && Array.isArray(prop.enum) ? prop.enum.filter((v): v is number => typeof v === "number") : [];
  return values.length ? Math.max(...values) : undefined;
}

function component(openapi: unknown, name: string): Schema | null {
  const schemas = isObj(openapi) && isObj(openapi.components) ? openapi.components.schemas : null;
  const s = isObj(schemas) ? schemas[name] : null;
  return isObj(s) && isObj(s.properties) ? (s.properties as Schema) : null;
}

/** The limits in an OpenAPI document; whatever it lacks keeps its default. */
export function limitsFromSchema(openapi: unknown, defaults: Limits = DEFAULT_LIMITS): Limits {
  const job = component(openapi, "JobCreate") ?? {};
  const path = component(openapi, "TrajectoryIn") ?? {};
  const pick = (v: number | undefined, d: number) => (v !== undefined && Number.isFinite(v) ? v : d);
  // a drawn point is [x, z]: its items' bounds are the coordinate limit
  const points = path.points;
  const pointSchema = isObj(points) && Array.isArray(points.anyOf) ? points.anyOf.find((b) => isObj(b) && b.type === "array") : null;
  const item = isObj(pointSchema) && isObj(pointSchema.items) ? pointSchema.items : null;
  const coord = isObj(item) && Array.isArray(item.prefixItems) ? constraint(item.prefixItems[0], "maximum") : undefined;
  return {
    promptMax: pick(constraint(job.prompt, "maxLength"), defaults.promptMax),
    secondsMin: pick(constraint(job.seconds, "minimum"), defaults.secondsMin),
    secondsMax: pick(constraint(job.seconds, "maximum"), defaults.secondsMax),
    seedMax: pick(constraint(job.seed, "maximum"), defaults.seedMax),
    personsMax: pick(enumMax(job.persons), defaults.personsMax),
    pathPoints: pick(constraint(points, "maxItems"), defaults.pathPoints),
    pathCoord: pick(coord, defaults.pathCoord),
  };
}

/** Fetch the API's schema and read its limits (the defaults when it cannot be had). */
export async function fetchLimits(url = "/openapi.json"): Promise<Limits> {
  try {
    const res = await fetch(url);
    if (!res.ok) return DEFAULT_LIMITS;
    return limitsFromSchema(await res.json());
  } catch {
    return DEFAULT_LIMITS;
  }
}
