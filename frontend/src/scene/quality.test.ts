import { describe, expect, it } from "vitest";
import { qualityFor } from "./quality";

describe("render quality", () => {
  it("uses light settings on software rasterisers", () => {
    expect(qualityFor("ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero)), SwiftShader driver)")).toBe("light");
    expect(qualityFor("llvmpipe (LLVM 15.0.6, 256 bits)")).toBe("light");
    expect(qualityFor("ANGLE (NVIDIA, NVIDIA GeForce RTX 3060 Direct3D11 vs_5_0 ps_5_0)")).toBe("full");
    expect(qualityFor("Apple M2")).toBe("full");
  });

  it("lets ?quality= override, ignoring unknown values", () => {
    expect(qualityFor("SwiftShader", "full")).toBe("full");
    expect(qualityFor("Apple M2", "light")).toBe("light");
    expect(qualityFor("Apple M2", "ultra")).toBe("full");
  });

});
