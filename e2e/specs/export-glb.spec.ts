// "GLB" in Share & export downloads the motion as binary glTF 2.0 (GET
// /api/motions/{id}/export?format=glb): one file for everyone, a skinned character and a skin
// per person, one animation. Checked from the downloaded bytes: the glTF magic, version 2, the
// length in the header, and the JSON chunk's skins, meshes and animation.
import { expect, test } from "@playwright/test";
import { readFileSync } from "node:fs";
import { makeMotion, openStudio, shot } from "./studio";

/** The header and JSON chunk of a GLB. */
function readGlb(bytes: Buffer): { magic: string; version: number; length: number; json: { skins: { joints: number[] }[]; meshes?: unknown[]; animations: { channels: unknown[] }[]; nodes: { name?: string }[]; extras?: Record<string, unknown> } } {
  const magic = bytes.subarray(0, 4).toString("latin1");
  const version = bytes.readUInt32LE(4);
  const length = bytes.readUInt32LE(8);
  const chunk = bytes.readUInt32LE(12);
  expect(bytes.subarray(16, 20).toString("latin1")).toBe("JSON");
  return { magic, version, length, json: JSON.parse(bytes.subarray(20, 20 + chunk).toString("utf8")) };
}

for (const persons of [1, 2] as const) {
  test(`"GLB" downloads a binary glTF of the motion (${persons} ${persons === 1 ? "person" : "people"})`, async ({ page, request }, info) => {
    const id = await makeMotion(request, { prompt: persons === 1 ? "a person jumps" : "two people dance salsa", persons, seconds: 2 }, 120_000);
    await openStudio(page, `/m/${id}`);
    await page.waitForFunction(() => window.__interplay.phase === "done");
    const button = page.getByRole("link", { name: "Download GLB" });
    await expect(button).toHaveAttribute("href", new RegExp(`/api/motions/${id}/export\\?format=glb$`));

    const download = page.waitForEvent("download");
    await button.click();
    const file = await download;
    expect(file.suggestedFilename()).toBe(`interplay-${persons === 1 ? "a-person-jumps" : "two-people-dance-salsa"}-${id}.glb`);
    const bytes = readFileSync((await file.path())!);
    const glb = readGlb(bytes);
    expect(glb.magic).toBe("glTF");
    expect(glb.version).toBe(2);
    expect(glb.length).toBe(bytes.length);
    expect(glb.json.skins).toHaveLength(persons);
    expect(glb.json.meshes).toHaveLength(persons); // a skinned body each
    expect(glb.json.animations).toHaveLength(1); // one clip for everyone
    // per person: the pelvis's translation and the 22 joints' rotations
    expect(glb.json.animations[0].channels).toHaveLength(persons * 23);
    const names = glb.json.nodes.map((n) => n.name);
    for (let p = 1; p <= persons; p++) expect(names).toContain(`person${p}_body`); // Person 1, Person 2
    await shot(page, `export-glb-${persons}`, info);
  });
}

test("the export presets go into the GLB: 30 fps, centimetres, Mixamo names", async ({ page, request }) => {
  const id = await makeMotion(request, { prompt: "two people dance salsa", persons: 2, seconds: 2 }, 120_000);
  await openStudio(page, `/m/${id}`);
  await page.waitForFunction(() => window.__interplay.phase === "done");
  await page.getByTestId("export-presets").locator("summary").click();
  await page.getByTestId("preset-fps").selectOption("30");
  await page.getByTestId("preset-units").selectOption("cm");
  await page.getByTestId("preset-names").selectOption("mixamo");
  const button = page.getByRole("link", { name: "Download GLB" });
  await expect(button).toHaveAttribute("href", new RegExp(`format=glb&fps=30&units=cm&names=mixamo$`));
  await expect(page.getByTestId("export-bvh-0")).toHaveAttribute("href", /fps=30&units=cm&names=mixamo$/);
  const download = page.waitForEvent("download");
  await button.click();
  const glb = readGlb(readFileSync((await (await download).path())!));
  expect(glb.json.extras).toMatchObject({ fps: 30, units: "cm", names: "mixamo" });
  const frames = (await (await request.get(`/api/motions/${id}`)).json()).people[0].joints.length;
  expect(glb.json.extras?.frames).toBe(Math.ceil(((frames - 1) / 20) * 30 - 1e-6) + 1); // the last pose kept
  for (let p = 0; p < 2; p++) {
    const bones = glb.json.skins[p].joints.map((n) => glb.json.nodes[n].name);
    expect(bones[0]).toBe(`person${p + 1}_mixamorig:Hips`); // each person's bones apart
    expect(bones).toContain(`person${p + 1}_mixamorig:HeadTop_End`);
  }
});
