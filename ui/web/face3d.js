// The visit's 3D face in WebGL (three.js from Debian's libjs-three, served
// by the office server from /usr/share/javascript/three): the textured
// mesh (decimated by the server; the full mesh on request), the traces
// coloured by set, the blocks by verdict, the range pole; drag to turn, wheel to zoom, a
// click on the face marks a point and a second click gives the distance.
import * as THREE from '/three/build/three.module.js';
import { OrbitControls } from '/three/examples/jsm/controls/OrbitControls.js';
import { setColour, verdictColours } from './dom.js';

function parseMesh(buffer) {
  const v = new DataView(buffer);
  const magic = String.fromCharCode(v.getUint8(0), v.getUint8(1), v.getUint8(2), v.getUint8(3));
  if (magic !== 'RFM1') throw new Error('the face is not in the expected form');
  const n = v.getUint32(4, true), t = v.getUint32(8, true), hasUv = v.getUint32(12, true) === 1;
  let at = 40;
  const xyz = new Float32Array(buffer.slice(at, at + n * 12)); at += n * 12;
  let uv = null;
  if (hasUv) { uv = new Float32Array(buffer.slice(at, at + n * 8)); at += n * 8; }
  const index = new Uint32Array(buffer.slice(at, at + t * 12));
  return { xyz, uv, index, triangles: t };
}

export async function showFace(host, status, meshUrl, textureUrl, visit) {
  const width = host.clientWidth || 600;
  const height = Math.max(260, Math.min(520, Math.round(width * 0.7)));
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(width, height);
  renderer.setClearColor(0x20242a);
  renderer.domElement.id = 'face-canvas';
  host.replaceChildren(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(45, width / height, 0.01, 1000);
  scene.add(new THREE.AmbientLight(0xffffff, 0.85));
  const sun = new THREE.DirectionalLight(0xffffff, 0.4);
  sun.position.set(1, 1, 2);
  scene.add(sun);

  const started = performance.now();
  const r = await fetch(meshUrl, { credentials: 'same-origin' });
  if (!r.ok) throw new Error('the 3D face could not be read');
  const buffer = await r.arrayBuffer();
  const m = parseMesh(buffer);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(m.xyz, 3));
  if (m.uv) geometry.setAttribute('uv', new THREE.BufferAttribute(m.uv, 2));
  geometry.setIndex(new THREE.BufferAttribute(m.index, 1));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
  const material = new THREE.MeshLambertMaterial({ color: 0xb0a898, side: THREE.DoubleSide });
  if (m.uv && textureUrl) {
    new THREE.TextureLoader().load(textureUrl, (tex) => {
      tex.flipY = false;  // the stored texture coordinates have v down
      material.map = tex;
      material.color.set(0xffffff);
      material.needsUpdate = true;
    });
  }
  const face = new THREE.Mesh(geometry, material);
  scene.add(face);

  // Each overlay carries what it shows in userData (trace or block, its
  // label): with the scene kept on the host element (below), a test reads
  // the colour each trace and block is drawn in.
  for (const t of visit.traces) {
    const g = new THREE.BufferGeometry().setFromPoints(t.points.map((p) => new THREE.Vector3(p[0], p[1], p[2])));
    const line = new THREE.Line(g, new THREE.LineBasicMaterial({ color: setColour(t.set), linewidth: 2 }));
    line.userData = { trace: t.label };
    scene.add(line);
  }
  for (const b of visit.blocks) {
    const colour = verdictColours[b.verdict_kind] || '#888888';
    const pts = b.vertices.map((p) => new THREE.Vector3(p[0], p[1], p[2]));
    let drawn = null;
    if (b.faces.length) {
      const positions = [];
      for (const f of b.faces)
        for (let i = 1; i + 1 < f.length; ++i) for (const k of [f[0], f[i], f[i + 1]]) positions.push(pts[k].x, pts[k].y, pts[k].z);
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
      drawn = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.45, side: THREE.DoubleSide }));
    } else if (pts.length > 1) {
      drawn = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(pts), new THREE.LineBasicMaterial({ color: colour }));
    }
    if (drawn) {
      drawn.userData = { block: b.label };
      scene.add(drawn);
    }
  }

  // The range pole that scaled the face: its two targets and the pole
  // between them, in orange.
  if (visit.pole) {
    const [a, b] = visit.pole.targets.map((p) => new THREE.Vector3(p[0], p[1], p[2]));
    scene.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints([a, b]), new THREE.LineBasicMaterial({ color: 0xff8c00 })));
    const r = Math.max(a.distanceTo(b) / 40, 0.005);
    for (const p of [a, b]) {
      const target = new THREE.Mesh(new THREE.SphereGeometry(r, 12, 12), new THREE.MeshBasicMaterial({ color: 0xff8c00 }));
      target.position.copy(p);
      scene.add(target);
    }
    host.dataset.pole = 'yes';
  }
  const sphere = geometry.boundingSphere;
  const radius = sphere && sphere.radius > 0 ? sphere.radius : 1;
  const centre = sphere ? sphere.center : new THREE.Vector3();
  // The face seen from in front: its mean normal, from the mesh's normals.
  const normals = geometry.getAttribute('normal');
  const view = new THREE.Vector3();
  for (let i = 0; i < normals.count; i += Math.max(1, Math.floor(normals.count / 2000)))
    view.add(new THREE.Vector3(normals.getX(i), normals.getY(i), normals.getZ(i)));
  if (view.lengthSq() < 1e-12) view.set(0, -1, 0);
  view.normalize();
  camera.up.set(0, 0, 1);
  camera.position.copy(centre).addScaledVector(view, radius * 2.6);
  camera.near = radius / 100;
  camera.far = radius * 100;
  camera.updateProjectionMatrix();
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();

  // A click marks a point on the face; the next gives the distance.
  const ray = new THREE.Raycaster();
  let first = null, marker = null;
  renderer.domElement.addEventListener('dblclick', (e) => {
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
    ray.setFromCamera(ndc, camera);
    const hit = ray.intersectObject(face)[0];
    if (!hit) return;
    if (!first) {
      first = hit.point.clone();
      marker = new THREE.Mesh(new THREE.SphereGeometry(radius / 100, 8, 8), new THREE.MeshBasicMaterial({ color: 0xffff00 }));
      marker.position.copy(first);
      scene.add(marker);
      status.textContent = 'Double-click a second point on the face for the distance.';
    } else {
      const d = first.distanceTo(hit.point);
      status.textContent = `Distance: ${d.toFixed(3)} m (the face's precision: see its figures)`;
      // The two points measured (the mesh's frame), for a test to check
      // that they lie on the face.
      host.dataset.measuredFrom = first.toArray().join(' ');
      host.dataset.measuredTo = hit.point.toArray().join(' ');
      scene.remove(marker);
      first = null;
    }
  });

  const render = () => renderer.render(scene, camera);
  controls.addEventListener('change', render);
  const loop = () => { render(); if (document.body.contains(renderer.domElement)) requestAnimationFrame(loop); };
  loop();
  const seconds = (performance.now() - started) / 1000;
  status.textContent = `${m.triangles} triangles, ${(buffer.byteLength / 1024).toFixed(1)} kB in ${seconds.toFixed(2)} s. Drag to turn, wheel to zoom, double-click two points to measure.`;
  host.faceScene = scene;
  host.dataset.drawn = 'yes';
}
