// Converts the npm package `bunny` (positions + cells) into scenes/assets/bunny.obj, normalised for the scenes.
// Usage: node make_bunny.mjs <path of the installed bunny package> <output .obj>   (scripts/make_bunny.sh runs it)
import { createRequire } from 'node:module';
import { renameSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';

// Scene 2 (and 5, 10) place the mesh with `Scale 0.7` at `Translation 1 0 -2` in a 10-unit Cornell box:
// standing on y = 0 and 3 units tall it ends up 2.1 units tall there, about 2.2 wide, clear of the walls.
const kHeight = 3.0;

const [pkgDir, outPath] = process.argv.slice(2);
if (!pkgDir || !outPath) {
  console.error('usage: node make_bunny.mjs <bunny package folder> <output.obj>');
  process.exit(2);
}

const require = createRequire(import.meta.url);
const pkg = require(resolve(pkgDir, 'package.json'));
const { positions, cells } = require(resolve(pkgDir));
if (!Array.isArray(positions) || !Array.isArray(cells) || positions.length === 0 || cells.length === 0) {
  console.error(`make_bunny: ${pkgDir} has no positions/cells arrays`);
  process.exit(1);
}

// The package is already +Y up (ears at the top, face towards -X as in the original scan): only a
// uniform scale and a translation are applied, so the shape is untouched.
const lo = [Infinity, Infinity, Infinity];
const hi = [-Infinity, -Infinity, -Infinity];
for (const p of positions) {
  for (let i = 0; i < 3; i++) {
    lo[i] = Math.min(lo[i], p[i]);
    hi[i] = Math.max(hi[i], p[i]);
  }
}
const scale = kHeight / (hi[1] - lo[1]);
const offset = [-(lo[0] + hi[0]) / 2, -lo[1], -(lo[2] + hi[2]) / 2];
const fmt = (x) => (Math.abs(x) < 5e-7 ? 0 : x).toFixed(6);
const width = ((hi[0] - lo[0]) * scale).toFixed(2);
const depth = ((hi[2] - lo[2]) * scale).toFixed(2);

const lines = [
  `# bunny.obj: the Stanford bunny, LOW-RESOLUTION version (${positions.length} vertices, ${cells.length} triangles),`,
  `# from the npm package \`bunny\` ${pkg.version} (Mikola Lysenko, public domain), itself from the Stanford 3D`,
  '# Scanning Repository (graphics.stanford.edu/data/3Dscanrep). The thesis used a 70064-triangle version',
  '# (dt-grid stanford_bunny.obj) that cannot be fetched here.',
  '# Written by scenes/assets/make_bunny.mjs (run scripts/make_bunny.sh). Closed mesh, positions only',
  '# (no vt/vn), faces wound counter-clockwise seen from outside.',
  `# Normalised: +Y up, face towards -X as in the original scan, uniformly scaled to ${kHeight.toFixed(1)} units tall`,
  `# (${width} along x, ${depth} along z), standing on y = 0, bounding box centred on x = z = 0.`,
];
for (const p of positions) {
  lines.push(`v ${fmt((p[0] + offset[0]) * scale)} ${fmt((p[1] + offset[1]) * scale)} ${fmt((p[2] + offset[2]) * scale)}`);
}
for (const c of cells) {
  if (c.length !== 3) {
    console.error(`make_bunny: cell with ${c.length} vertices`);
    process.exit(1);
  }
  lines.push(`f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}`);
}

// Written beside the target and renamed, so an interrupted run never leaves a truncated bunny.obj.
const tmpPath = `${outPath}.tmp${process.pid}`;
writeFileSync(tmpPath, lines.join('\n') + '\n');
renameSync(tmpPath, outPath);
console.error(`make_bunny: wrote ${outPath} (${positions.length} vertices, ${cells.length} triangles)`);
