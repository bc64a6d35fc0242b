// The texture of the blob shadows drawn under a mannequin when there is no shadow map.
import * as THREE from "three";

let blobTexture: THREE.Texture | null = null;

/** A soft round shadow: a radial gradient from dark to clear (made once). */
export function blobMap(): THREE.Texture {
  if (blobTexture) return blobTexture;
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const ctx = canvas.getContext("2d")!;
  const g = ctx.createRadialGradient(32, 32, 0, 32, 32, 32);
  g.addColorStop(0, "rgba(0,0,0,1)");
  g.addColorStop(0.5, "rgba(0,0,0,0.55)");
  g.addColorStop(1, "rgba(0,0,0,0)");
  ctx.fillStyle = g;
  ctx.fillRect(0, 0, 64, 64);
  blobTexture = new THREE.CanvasTexture(canvas);
  return blobTexture;
}

