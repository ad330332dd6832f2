// The 3D view of a voxel world: the script of the page render_voxel_html() writes
// (drawing/src/voxel_html.cpp). three.js and OrbitControls come from the page's import map, the
// world from its <script id="world">. Voxel (x, y, z) is drawn centred at (x, -y, z): z up, and
// seen from above the world looks as the 2D pictures do, row 0 at the back.
import * as THREE from 'three';
import {OrbitControls} from 'three/addons/controls/OrbitControls.js';

const world = JSON.parse(document.getElementById('world').textContent);
const status = document.getElementById('status');
const colour = (name) => new THREE.Color(world.colours[name]);
const [width, height, depth] = world.size;
const at = (x, y, z) => new THREE.Vector3(x, -y, z);

// The surface cubes' indices in the grid of cubes, from the runs the page carries.
function decodeCubes() {
  const bytes = Uint8Array.from(atob(world.cubes), (c) => c.charCodeAt(0));
  const cubes = [];
  let index = 0, drawn = false, position = 0;
  while (position < bytes.length) {
    let run = 0, scale = 1, byte;
    do {
      byte = bytes[position++];
      run += (byte & 127) * scale;
      scale *= 128;
    } while (byte & 128);
    if (drawn) for (let i = 0; i < run; ++i) cubes.push(index + i);
    index += run;
    drawn = !drawn;
  }
  return cubes;
}

// The blocked voxels: one instanced cube each, coloured by height, in ascending z (the runs'
// order), so that showing the layers up to z is drawing the first cubes.
function obstacles() {
  const [gw, gh] = world.grid, cell = world.cell;
  const cubes = decodeCubes();
  const mesh = new THREE.InstancedMesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshLambertMaterial(),
                                       Math.max(cubes.length, 1));
  const low = colour('voxelLow'), high = colour('voxelHigh'), shade = new THREE.Color();
  const matrix = new THREE.Matrix4(), scale = new THREE.Vector3(), quaternion = new THREE.Quaternion();
  const firstAbove = new Array(depth).fill(cubes.length);  // per layer z: the first cube above it
  let layersDone = 0;  // the layers below it have their firstAbove
  const span = (i, size) => [i * cell, Math.min((i + 1) * cell, size)];
  cubes.forEach((index, n) => {
    const x = index % gw, y = Math.floor(index / gw) % gh, z = Math.floor(index / (gw * gh));
    const [x0, x1] = span(x, width), [y0, y1] = span(y, height), [z0, z1] = span(z, depth);
    while (layersDone < z0) firstAbove[layersDone++] = n;
    scale.set(x1 - x0, y1 - y0, z1 - z0);
    matrix.compose(at((x0 + x1 - 1) / 2, (y0 + y1 - 1) / 2, (z0 + z1 - 1) / 2), quaternion, scale);
    mesh.setMatrixAt(n, matrix);
    mesh.setColorAt(n, shade.copy(low).lerp(high, depth > 1 ? (z0 + z1 - 1) / 2 / (depth - 1) : 0));
  });
  mesh.count = cubes.length;
  return {mesh, firstAbove, total: cubes.length};
}

// Tubes along a polyline: a cylinder per segment, a ball per corner.
function tubes(points, radius, material) {
  const group = new THREE.Group();
  if (points.length === 0) return group;
  const balls = new THREE.InstancedMesh(new THREE.SphereGeometry(radius, 16, 12), material, points.length);
  const rods = new THREE.InstancedMesh(new THREE.CylinderGeometry(radius, radius, 1, 16, 1, true), material,
                                       Math.max(points.length - 1, 1));
  const matrix = new THREE.Matrix4(), up = new THREE.Vector3(0, 1, 0), one = new THREE.Vector3(1, 1, 1);
  points.forEach((p, i) => balls.setMatrixAt(i, matrix.makeTranslation(p.x, p.y, p.z)));
  let rodCount = 0;
  for (let i = 0; i + 1 < points.length; ++i) {
    const along = new THREE.Vector3().subVectors(points[i + 1], points[i]);
    const length = along.length();
    if (length === 0) continue;
    const turn = new THREE.Quaternion().setFromUnitVectors(up, along.clone().divideScalar(length));
    const middle = new THREE.Vector3().addVectors(points[i], points[i + 1]).multiplyScalar(0.5);
    rods.setMatrixAt(rodCount++, matrix.compose(middle, turn, one.clone().setY(length)));
  }
  rods.count = rodCount;
  group.add(balls, rods);
  return group;
}

const triples = (flat, size = 3) => Array.from({length: flat.length / size}, (_, i) => flat.slice(i * size, i * size + size));

function build(scene) {
  const shape = obstacles();
  scene.add(shape.mesh);
  const extent = Math.max(width, height, depth);
  const radius = Math.min(2, Math.max(0.12, extent * 0.006));
  const path = triples(world.path).map(([x, y, z]) => at(x, y, z));
  scene.add(tubes(path, radius, new THREE.MeshLambertMaterial({color: colour('path')})));
  if (world.gridPath.length) {
    const points = triples(world.gridPath).map(([x, y, z]) => at(x, y, z));
    scene.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(points),
                             new THREE.LineBasicMaterial({color: colour('gridPath')})));
  }
  const endRadius = Math.max(0.45, radius * 2.5, extent * 0.02);
  for (const [name, cell] of [['start', world.start], ['goal', world.goal]]) {
    if (!cell) continue;
    const ball = new THREE.Mesh(new THREE.SphereGeometry(endRadius, 24, 16),
                                new THREE.MeshLambertMaterial({color: colour(name)}));
    ball.position.copy(at(...cell));
    scene.add(ball);
  }
  const pheromone = triples(world.pheromone, 4);
  if (pheromone.length) {
    const dots = new THREE.InstancedMesh(new THREE.IcosahedronGeometry(1, 1), new THREE.MeshLambertMaterial(),
                                         pheromone.length);
    const weak = colour('pheromoneWeak'), strong = colour('pheromoneStrong'), shade = new THREE.Color();
    const matrix = new THREE.Matrix4(), turn = new THREE.Quaternion();
    pheromone.forEach(([x, y, z, amount], i) => {
      const size = 0.1 + 0.25 * amount;
      dots.setMatrixAt(i, matrix.compose(at(x, y, z), turn, new THREE.Vector3(size, size, size)));
      dots.setColorAt(i, shade.copy(weak).lerp(strong, amount));
    });
    scene.add(dots);
  }
  // The world's box.
  const box = new THREE.Box3(at(-0.5, height - 0.5, -0.5), at(width - 0.5, -0.5, depth - 0.5));
  scene.add(new THREE.Box3Helper(box, colour('frame')));
  return {shape, box};
}

try {
  const canvas = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({canvas, antialias: true});
  renderer.setPixelRatio(window.devicePixelRatio);
  const size = () => [canvas.clientWidth, canvas.clientHeight];
  renderer.setSize(...size(), false);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color('#fafafa');
  scene.add(new THREE.AmbientLight(0xffffff, 1.1));
  const sun = new THREE.DirectionalLight(0xffffff, 2.0);
  sun.position.set(0.5, -0.8, 1.2);  // from the front right, above: top, front and right faces differ
  scene.add(sun);
  const {shape, box} = build(scene);

  // Seen from the front right (x high, rows high), above; the whole box in view.
  const centre = box.getCenter(new THREE.Vector3());
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  const camera = new THREE.PerspectiveCamera(40, size()[0] / size()[1], 0.01, 1);
  camera.up.set(0, 0, 1);
  const fit = sphere.radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
  const distance = fit / Math.min(1, camera.aspect);
  camera.position.copy(centre).add(new THREE.Vector3(0.55, -0.75, 0.65).normalize().multiplyScalar(distance));
  camera.near = distance / 1000;
  camera.far = distance * 10;
  camera.updateProjectionMatrix();
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(centre);
  controls.update();

  const render = () => renderer.render(scene, camera);
  controls.addEventListener('change', render);
  window.addEventListener('resize', () => {
    camera.aspect = size()[0] / size()[1];
    camera.updateProjectionMatrix();
    renderer.setSize(...size(), false);
    render();
  });
  document.getElementById('see-through').addEventListener('change', (event) => {
    const material = shape.mesh.material;
    material.transparent = event.target.checked;
    material.opacity = event.target.checked ? 0.25 : 1;
    material.depthWrite = !event.target.checked;
    material.needsUpdate = true;
    render();
  });
  document.getElementById('layers').addEventListener('input', (event) => {
    const top = Number(event.target.value);
    document.getElementById('top-layer').textContent = top;
    shape.mesh.count = top + 1 < depth ? shape.firstAbove[top] : shape.total;
    render();
  });
  render();
  status.textContent = `${shape.total.toLocaleString('en')} cubes drawn.`;
  document.body.dataset.rendered = String(shape.total);
} catch (error) {
  status.textContent = `The 3D view needs WebGL: ${error.message}`;
  status.className = 'error';
  document.body.dataset.error = error.message;
}
