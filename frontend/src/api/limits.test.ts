// @vitest-environment node
import { describe, expect, it } from "vitest";
import { DEFAULT_LIMITS, limitsFromSchema } from "./limits";

// The parts of the API's /openapi.json the page reads (the shapes pydantic writes).
const schema = {
  components: {
    schemas: {
      JobCreate: {
        properties: {
          prompt: { anyOf: [{ type: "string" }, { type: "null" }], maxLength: 420 },
          seconds: { type: "number", minimum: 2, maximum: 12 },
          seed: { anyOf: [{ type: "integer", minimum: 0, maximum: 999 }, { type: "null" }] },
          persons: { type: "integer", enum: [1, 2, 3] },
        },
      },
      TrajectoryIn: {
        properties: {
          points: {
            anyOf: [
              { type: "array", maxItems: 50, items: { type: "array", prefixItems: [{ type: "number", minimum: -30, maximum: 30 }, { type: "number" }] } },
              { type: "null" },
            ],
          },
        },
      },
    },
  },
};

describe("limitsFromSchema", () => {
  it("reads the prompt, seconds, seed and path limits from the API's schema", () => {
    expect(limitsFromSchema(schema)).toEqual({ promptMax: 420, secondsMin: 2, secondsMax: 12, seedMax: 999, personsMax: 3, pathPoints: 50, pathCoord: 30 });
  });

  it("keeps the defaults for what the schema lacks or when there is none", () => {
    expect(limitsFromSchema(null)).toEqual(DEFAULT_LIMITS);
    expect(limitsFromSchema({ components: { schemas: { JobCreate: { properties: { seconds: { maximum: 30 } } } } } })).toEqual({
      ...DEFAULT_LIMITS,
      secondsMax: 30,
    });
  });
});
