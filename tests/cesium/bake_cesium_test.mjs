// A real client reads a baked tileset: bakes a small quantized-mesh tileset with `globe bake`,
// serves it with CesiumJS from a loopback HTTP server, loads it in headless Chromium, and checks that
// the client requested and decoded the tiles without errors and that sampleTerrainMostDetailed
// agrees with `globe planet sample`. Writes WORK/cesium_view.png (the client's view).
// Usage: node bake_cesium_test.mjs GLOBE PLANET WORK
import { execFileSync, spawn } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const [globe, planet, work] = process.argv.slice(2);
const cesiumDir = path.join(here, "node_modules", "cesium", "Build", "Cesium");
const tilesDir = path.join(work, "tiles");
const LEVELS = [0, 10];
const REGION = { west: -99.03, south: 38.97, east: -98.97, north: 39.03 };
const CELLS = 64; // kMeshCells: grid samples per tile side
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); console.log(`${ok ? "ok  " : "FAIL"} ${what}`); };

fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
const region = `${REGION.west},${REGION.south},${REGION.east},${REGION.north}`;
console.log(execFileSync(globe, ["bake", "--planet", planet, "--format", "quantized-mesh", "--levels",
  `${LEVELS[0]}..${LEVELS[1]}`, "--region", region, "--out", tilesDir], { encoding: "utf8" }).trim());

// Test points: samples of the finest level's grid inside the region (off the tiles' edges, where a
// client may take the coarser parent), at which the mesh holds the model's height up to the
// simplification, bounded by the level's geometric error.
const step = 180 / (2 ** LEVELS[1] * CELLS);
const points = [];
const gi0 = Math.ceil((REGION.west + 180) / step), gj0 = Math.ceil((REGION.south + 90) / step);
const gi1 = Math.floor((REGION.east + 180) / step), gj1 = Math.floor((REGION.north + 90) / step);
for (let k = 0; points.length < 10; ++k) {
  const gi = gi0 + 1 + ((k * 37) % (gi1 - gi0 - 1)), gj = gj0 + 1 + ((k * 23) % (gj1 - gj0 - 1));
  if (gi % CELLS !== 0 && gj % CELLS !== 0) points.push({ lon: -180 + gi * step, lat: -90 + gj * step });
}
const sampleArgs = ["planet", "sample", planet];
for (const p of points) sampleArgs.push("--at", `${p.lat.toPrecision(17)},${p.lon.toPrecision(17)}`);
const expected = execFileSync(globe, sampleArgs, { encoding: "utf8" }).trim().split("\n").map((l) => Number(l.split(" ")[1]));
const radius = JSON.parse(fs.readFileSync(path.join(tilesDir, "layer.json"), "utf8")).globe_radius_m;
// The level's geometric error (levelGeometricError_m) bounds the simplification.
const levelError = (radius * 2 * Math.PI * 0.25) / (65 * 2) / 2 ** LEVELS[1];
const quantization = 1.0; // metres: a tile's height range over 32767 steps, far below 1 m here

const config = {
  radius_m: radius, points,
  view: { lon: (REGION.west + REGION.east) / 2, lat: (REGION.south + REGION.north) / 2, back_deg: 0.09, height_m: 9000, pitch_deg: -25 },
};
const types = { ".js": "text/javascript", ".css": "text/css", ".json": "application/json", ".html": "text/html",
  ".png": "image/png", ".jpg": "image/jpeg", ".svg": "image/svg+xml", ".wasm": "application/wasm",
  ".terrain": "application/vnd.quantized-mesh", ".xml": "application/xml", ".glb": "model/gltf-binary" };
const requests = [];
let resolveResult;
const result = new Promise((resolve) => { resolveResult = resolve; });

function serveFile(res, root, rel) {
  const file = path.join(root, path.normalize("/" + rel));
  if (!file.startsWith(root) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.writeHead(404).end();
    return 404;
  }
  res.writeHead(200, { "Content-Type": types[path.extname(file)] || "application/octet-stream" });
  res.end(fs.readFileSync(file));
  return 200;
}

const server = http.createServer((req, res) => {
  const url = new URL(req.url, "http://127.0.0.1");
  if (req.method === "POST" && url.pathname === "/result") {
    let body = "";
    req.on("data", (c) => { body += c; });
    req.on("end", () => { res.writeHead(204).end(); resolveResult(JSON.parse(body)); });
    return;
  }
  let status;
  if (url.pathname === "/favicon.ico") { res.writeHead(204).end(); status = 204; }
  else if (url.pathname === "/") status = serveFile(res, here, "page.html");
  else if (url.pathname === "/page.js") status = serveFile(res, here, "page.js");
  else if (url.pathname === "/config.json") { res.writeHead(200, { "Content-Type": "application/json" }).end(JSON.stringify(config)); status = 200; }
  else if (url.pathname.startsWith("/cesium/")) status = serveFile(res, cesiumDir, url.pathname.slice(8));
  else if (url.pathname.startsWith("/tiles/")) status = serveFile(res, tilesDir, url.pathname.slice(7));
  else { res.writeHead(404).end(); status = 404; }
  requests.push({ path: url.pathname, status });
});
await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
const url = `http://127.0.0.1:${server.address().port}/`;

// Only loopback: every host name but 127.0.0.1 resolves to nothing, background services are off.
const browser = spawn("chromium", ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
  "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist", "--window-size=960,640",
  "--no-first-run", "--no-default-browser-check", "--disable-background-networking", "--disable-component-update",
  "--disable-sync", "--disable-default-apps", "--disable-extensions", "--metrics-recording-only",
  "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1", `--user-data-dir=${path.join(work, "profile")}`, url],
  { stdio: ["ignore", "ignore", "pipe"] });
let browserLog = "";
browser.stderr.on("data", (c) => { browserLog += c; });
const timeout = new Promise((resolve) => setTimeout(() => resolve({ ok: false, errors: ["no result from the page within 120 s"] }), 120000));
const r = await Promise.race([result, timeout]);
browser.kill("SIGTERM");
server.close();
fs.writeFileSync(path.join(work, "chromium.log"), browserLog);

check(r.ok === true, `the page loaded the tileset and sampled it${r.ok ? "" : ": " + r.errors.join("; ")}`);
check((r.errors || []).length === 0, `no client errors${(r.errors || []).length ? ": " + r.errors.join("; ") : ""}`);
const tiles = requests.filter((q) => q.path.endsWith(".terrain"));
check(tiles.length >= 10 && tiles.every((q) => q.status === 200), `client requested ${tiles.length} tiles, all served`);
check(requests.some((q) => q.path === "/tiles/layer.json" && q.status === 200), "client read layer.json");
check(requests.every((q) => q.status < 300), `no missing files (${requests.filter((q) => q.status >= 300).map((q) => q.path).join(", ")})`);
if (r.ok) {
  check(r.tilesRendered > 0, `client rendered ${r.tilesRendered} decoded tiles`);
  fs.writeFileSync(path.join(work, "cesium_view.png"), Buffer.from(r.screenshot.split(",")[1], "base64"));
  console.log(`screenshot: ${path.join(work, "cesium_view.png")}`);
  points.forEach((p, k) => {
    if (typeof r.heights[k] !== "number") {
      check(false, `${p.lat},${p.lon}: the client has no height`);
      return;
    }
    const bound = levelError + quantization;
    const diff = Math.abs(r.heights[k] - expected[k]);
    check(diff <= bound, `${p.lat.toFixed(6)},${p.lon.toFixed(6)}: client ${r.heights[k].toFixed(3)} m, ` +
      `planet sample ${expected[k].toFixed(3)} m, |diff| ${diff.toFixed(3)} <= ${bound.toFixed(3)} m`);
  });
}
console.log(`${failures.length === 0 ? "passed" : "FAILED"}: ${failures.length} failures`);
process.exit(failures.length === 0 ? 0 : 1);
