// The client side of bake_cesium_test.mjs: loads the baked tileset with CesiumJS on a sphere of the
// planet's radius, renders a lit view of the baked region, samples the most detailed terrain at the
// test's points and posts everything (with the canvas as a PNG) back to the test's server.
"use strict";
const errors = [];
window.addEventListener("error", (e) => errors.push("page: " + e.message));
window.addEventListener("unhandledrejection", (e) => errors.push("promise: " + String(e.reason)));

function report(result) {
  return fetch("/result", { method: "POST", body: JSON.stringify(result) });
}

// Resolves once the globe has no tile left to load, for `settle` consecutive checks.
function tilesLoaded(scene, timeoutMs) {
  return new Promise((resolve, reject) => {
    let quiet = 0;
    const started = performance.now();
    const timer = setInterval(() => {
      quiet = scene.globe.tilesLoaded ? quiet + 1 : 0;
      if (quiet >= 5) {
        clearInterval(timer);
        resolve();
      } else if (performance.now() - started > timeoutMs) {
        clearInterval(timer);
        reject(new Error("tiles still loading after " + timeoutMs + " ms"));
      }
    }, 200);
  });
}

async function run() {
  const config = await (await fetch("/config.json")).json();
  const r = config.radius_m;
  const sphere = new Cesium.Ellipsoid(r, r, r);
  Cesium.Ellipsoid.default = sphere;
  const terrain = await Cesium.CesiumTerrainProvider.fromUrl("/tiles/", { requestVertexNormals: true, ellipsoid: sphere });
  terrain.errorEvent.addEventListener((e) => errors.push("terrain: " + e.message));
  const widget = new Cesium.CesiumWidget("view", {
    terrainProvider: terrain,
    baseLayer: false,
    skyBox: false,
    skyAtmosphere: false,
    contextOptions: { webgl: { preserveDrawingBuffer: true } },
  });
  const scene = widget.scene;
  scene.globe.baseColor = Cesium.Color.fromCssColorString("#8a9a6b");
  scene.globe.showGroundAtmosphere = false;
  scene.globe.enableLighting = true;
  scene.fog.enabled = false;
  const v = config.view;
  const target = Cesium.Cartesian3.fromDegrees(v.lon, v.lat, 0, sphere);
  const up = Cesium.Cartesian3.normalize(target, new Cesium.Cartesian3());
  const east = Cesium.Cartesian3.normalize(Cesium.Cartesian3.cross(Cesium.Cartesian3.UNIT_Z, up, new Cesium.Cartesian3()), new Cesium.Cartesian3());
  // A low sun from the west, so relief shows as light and shade.
  const light = Cesium.Cartesian3.add(Cesium.Cartesian3.multiplyByScalar(up, -0.5, new Cesium.Cartesian3()), east, new Cesium.Cartesian3());
  scene.light = new Cesium.DirectionalLight({ direction: Cesium.Cartesian3.normalize(light, light), intensity: 2.5 });
  scene.camera.setView({
    destination: Cesium.Cartesian3.fromDegrees(v.lon, v.lat - v.back_deg, v.height_m, sphere),
    orientation: { heading: 0, pitch: Cesium.Math.toRadians(v.pitch_deg), roll: 0 },
  });
  await tilesLoaded(scene, 60000);
  const points = config.points.map((p) => Cesium.Cartographic.fromDegrees(p.lon, p.lat));
  const sampled = await Cesium.sampleTerrainMostDetailed(terrain, points);
  widget.render();
  const screenshot = widget.canvas.toDataURL("image/png");
  await report({ ok: true, heights: sampled.map((c) => c.height), errors, screenshot,
                 tilesRendered: scene.globe._surface._tilesToRender.length });
}

run().catch((e) => report({ ok: false, errors: errors.concat(["exception: " + (e && e.stack ? e.stack : e)]) }));
