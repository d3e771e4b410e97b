// The toolpath page of `mbc run --html`: the moves as line segments in a
// three.js scene, orbit controls (rotate with the left button, pan with the
// right one, zoom with the wheel), view presets and axis labels, a slider
// and a play button that show the cut up to a move, and the source line of
// the move under the pointer. A lathe's page shows Z to the right and X up
// with the spindle axis; under cutter compensation the programmed contour
// is drawn beside the tool centre's path.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const data = JSON.parse(document.getElementById("toolpath").textContent);
const colors = [new THREE.Color(0x999999), new THREE.Color(0x1565c0), new THREE.Color(0x7b1fa2)];
const points = data.points; // x, y, z of each segment's two ends
const segments = points.length / 6;

// Rapids and cuts are two objects, the cuts drawn last: where a retract
// runs back up a plunge, the plunge shows. Each keeps, per segment, the
// move it belongs to, for the slider and the pointer.
function linesOf(wanted) {
  const where = [];
  for (let s = 0; s < segments; ++s) {
    if ((data.moves.kind[data.segmentMove[s]] === 0) === (wanted === 0)) {
      where.push(s);
    }
  }
  const position = new Float32Array(where.length * 6);
  const color = new Float32Array(where.length * 6);
  const move = new Uint32Array(where.length);
  where.forEach((s, i) => {
    position.set(points.slice(s * 6, s * 6 + 6), i * 6);
    move[i] = data.segmentMove[s];
    const c = colors[data.moves.kind[move[i]]];
    color.set([c.r, c.g, c.b, c.r, c.g, c.b], i * 6);
  });
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
  geometry.setAttribute("color", new THREE.BufferAttribute(color, 3));
  const object = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true }));
  object.userData.move = move;
  return object;
}
const rapids = linesOf(0);
const cuts = linesOf(1);
cuts.renderOrder = 1;
// The part in the scene, whose up is +y: a mill's Z up; a lathe's X up and
// Z to the right, machine (x, y, z) at (z, x, y).
const lathe = data.lathe;
const part = new THREE.Group();
if (lathe) {
  part.matrixAutoUpdate = false;
  part.matrix.set(0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1);
} else {
  part.rotation.x = -Math.PI / 2;
}
part.add(rapids, cuts);
part.updateMatrixWorld(true);
const geometry = new THREE.BufferGeometry();
geometry.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xffffff);
scene.add(part);
geometry.computeBoundingSphere();
geometry.computeBoundingBox();
const sphere = geometry.boundingSphere;
const radius = Math.max(sphere.radius, 1);
const center = sphere.center.clone().applyMatrix4(part.matrixWorld);
const axes = new THREE.AxesHelper(radius * 0.25);
part.add(axes);
const grid = new THREE.GridHelper(radius * 3, 15, 0xcccccc, 0xeeeeee);
if (lathe) {
  grid.rotation.x = Math.PI / 2; // the plane of X and Z
  grid.position.set(center.x, center.y, 0);
} else {
  grid.position.set(center.x, 0, center.z);
}
scene.add(grid);

// Labels at the ends of the axes the machine has.
function label(text, color) {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const context = canvas.getContext("2d");
  context.font = "bold 44px sans-serif";
  context.fillStyle = color;
  context.textAlign = "center";
  context.textBaseline = "middle";
  context.fillText(text, 32, 34);
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial(
    { map: new THREE.CanvasTexture(canvas), depthTest: false }));
  sprite.scale.setScalar(radius * 0.07);
  return sprite;
}
const labels = lathe ? ["X", "Z"] : ["X", "Y", "Z"];
for (const name of labels) {
  const sprite = label(name, { X: "#c62828", Y: "#2e7d32", Z: "#1565c0" }[name]);
  sprite.position.setComponent("XYZ".indexOf(name), radius * 0.31);
  part.add(sprite);
}

// A lathe's spindle axis, dash-dot under the part: Z at X 0.
if (lathe) {
  const box = geometry.boundingBox;
  const margin = (box.max.z - box.min.z) * 0.1 + radius * 0.05;
  const spindle = new THREE.BufferGeometry().setFromPoints([
    new THREE.Vector3(0, 0, box.min.z - margin), new THREE.Vector3(0, 0, box.max.z + margin)]);
  const line = new THREE.Line(spindle, new THREE.LineDashedMaterial(
    { color: 0x555555, dashSize: radius * 0.06, gapSize: radius * 0.025 }));
  line.computeLineDistances();
  part.add(line);
}

// The programmed contour where cutter compensation runs the tool beside it.
const programmed = data.programmed;
if (programmed.length) {
  const contour = new THREE.BufferGeometry();
  contour.setAttribute("position", new THREE.Float32BufferAttribute(programmed, 3));
  const lines = new THREE.LineSegments(contour, new THREE.LineDashedMaterial(
    { color: 0xef6c00, dashSize: radius * 0.02, gapSize: radius * 0.012 }));
  lines.computeLineDistances();
  part.add(lines);
}

const view = document.getElementById("view");
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 100);
const controls = new OrbitControls(camera, renderer.domElement);

// The views a backplot offers: where the camera looks from, in machine
// directions (the scene's up stays the machine's Z, a lathe's X). A
// lathe's front is its ZX view, Z to the right and X up; its top looks
// down X, its side along the spindle.
const views = lathe
  ? { front: [0, 1, 0], top: [1, 0.001, 0], side: [0, 0, 1], iso: [1, 1, 1] }
  : { top: [0, -0.001, 1], front: [0, -1, 0], side: [1, 0, 0], iso: [1.6, -2.2, 1.4] };
const screenOf = { X: [1, 0, 0], Y: [0, 1, 0], Z: [0, 0, 1] };
// Where the machine's axes point on the screen (a test reads it).
function screenDirections() {
  const origin = center.clone().project(camera);
  return labels.map((name) => {
    const tip = new THREE.Vector3(...screenOf[name]).transformDirection(part.matrixWorld)
      .multiplyScalar(radius * 0.5).add(center).project(camera);
    const dx = tip.x - origin.x, dy = tip.y - origin.y;
    const way = Math.max(Math.abs(dx), Math.abs(dy)) < 0.02 ? "depth"
      : Math.abs(dx) > Math.abs(dy) ? (dx > 0 ? "right" : "left") : (dy > 0 ? "up" : "down");
    return `${name}:${way}`;
  }).join(" ");
}
function setView(name) {
  const from = new THREE.Vector3(...views[name]).normalize().transformDirection(part.matrixWorld);
  camera.position.copy(center).addScaledVector(from, radius * 3.05);
  camera.up.set(0, 1, 0);
  controls.target.copy(center);
  controls.update();
  camera.updateMatrixWorld();
  document.documentElement.dataset.view = name;
  document.documentElement.dataset.screen = screenDirections();
  render();
}
const viewButtons = document.getElementById("views");
for (const name of Object.keys(views)) {
  const button = document.createElement("button");
  button.textContent = name;
  button.title = `view: ${name}`;
  button.addEventListener("click", () => setView(name));
  viewButtons.appendChild(button);
}

function resize() {
  renderer.setSize(view.clientWidth, view.clientHeight);
  camera.aspect = view.clientWidth / Math.max(view.clientHeight, 1);
  camera.updateProjectionMatrix();
  render();
}
function render() {
  renderer.render(scene, camera);
}
controls.addEventListener("change", render);
window.addEventListener("resize", resize);

// The cut up to move n: the segments of the moves before it.
const slider = document.getElementById("slider");
const position = document.getElementById("position");
const moveCount = data.moves.kind.length;
slider.max = moveCount;
slider.value = moveCount;
// Every move has at least one segment, in move order.
const firstSegment = new Uint32Array(moveCount + 1);
for (let s = segments - 1; s >= 0; --s) {
  firstSegment[data.segmentMove[s]] = s;
}
firstSegment[moveCount] = segments;
// The segments of an object that belong to the moves before `moves`.
function segmentsBefore(object, moves) {
  const move = object.userData.move;
  let low = 0, high = move.length;
  while (low < high) {
    const middle = (low + high) >> 1;
    if (move[middle] < moves) {
      low = middle + 1;
    } else {
      high = middle;
    }
  }
  return low;
}
function showUpTo(moves) {
  for (const object of [rapids, cuts]) {
    object.geometry.setDrawRange(0, segmentsBefore(object, moves) * 2);
  }
  position.textContent = `move ${moves} of ${moveCount}`;
  render();
}
slider.addEventListener("input", () => showUpTo(Number(slider.value)));
let playing = null;
document.getElementById("play").addEventListener("click", () => {
  if (playing) {
    clearInterval(playing);
    playing = null;
    return;
  }
  let moves = Number(slider.value) >= moveCount ? 0 : Number(slider.value);
  const step = Math.max(1, Math.ceil(moveCount / 300));
  playing = setInterval(() => {
    moves = Math.min(moveCount, moves + step);
    slider.value = moves;
    showUpTo(moves);
    if (moves >= moveCount) {
      clearInterval(playing);
      playing = null;
    }
  }, 33);
});

// The move under the pointer and its source line.
const tip = document.getElementById("tip");
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
const kinds = ["rapid", "feed", "arc"];
// A move's end as the control shows it (a lathe's X a diameter).
function endText(move) {
  return labels.map((name) => {
    const value = data.moves.end[move * 3 + "XYZ".indexOf(name)];
    const text = String(Math.round(value * 10000) / 10000);
    return `${name}${text.includes(".") ? text : text + "."}`;
  }).join(" ");
}
// What the tip says of the move at a point of the view (-1..1 both ways),
// or "" when no move is there.
function moveAt(x, y) {
  pointer.set(x, y);
  raycaster.params.Line.threshold = camera.position.distanceTo(controls.target) / 150;
  raycaster.setFromCamera(pointer, camera);
  // A cut before the rapid over it.
  const hit = raycaster.intersectObject(cuts)[0] ?? raycaster.intersectObject(rapids)[0];
  if (!hit) {
    return "";
  }
  const move = hit.object.userData.move[Math.floor(hit.index / 2)];
  const file = data.files[data.moves.file[move]];
  const line = data.moves.line[move];
  const text = data.source[`${data.moves.file[move]}:${line}`] ?? "";
  return `${file}:${line}  ${data.programs[data.moves.program[move]]}  ` +
         `${kinds[data.moves.kind[move]]} ${move + 1}  ${endText(move)}\n${text}`;
}
renderer.domElement.addEventListener("pointermove", (event) => {
  const box = renderer.domElement.getBoundingClientRect();
  const text = moveAt(((event.clientX - box.left) / box.width) * 2 - 1,
                      -((event.clientY - box.top) / box.height) * 2 + 1);
  tip.textContent = text;
  tip.style.left = `${event.clientX + 14}px`;
  tip.style.top = `${event.clientY + 14}px`;
  tip.style.display = text ? "block" : "none";
});

document.getElementById("title").textContent = data.title;
resize();
const wanted = /view=(\w+)/.exec(location.hash);
setView(wanted && views[wanted[1]] ? wanted[1] : lathe ? "front" : "iso");
showUpTo(moveCount);
// "#probe=N" (a test's): what the tip says at the middle of move N's
// first segment on the screen.
const probe = /probe=(\d+)/.exec(location.hash);
if (probe) {
  const s = firstSegment[Math.min(Number(probe[1]) - 1, moveCount - 1)];
  const middle = new THREE.Vector3().fromArray(points, s * 6)
    .add(new THREE.Vector3().fromArray(points, s * 6 + 3)).multiplyScalar(0.5);
  part.updateMatrixWorld();
  middle.applyMatrix4(part.matrixWorld).project(camera);
  document.documentElement.dataset.probe = moveAt(middle.x, middle.y);
}
// What a test reads once the first picture is drawn.
document.documentElement.dataset.programmed = programmed.length / 6;
document.documentElement.dataset.labels = labels.join(",");
document.documentElement.dataset.segments = segments;
document.documentElement.dataset.moves = moveCount;
document.documentElement.dataset.ready = "1";
