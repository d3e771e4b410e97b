// The toolpath page of `mbc run --html`: the moves as line segments in a
// three.js scene, orbit controls (rotate with the left button, pan with the
// right one, zoom with the wheel), a slider and a play button that show the
// cut up to a move, and the source line of the move under the pointer.
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
const part = new THREE.Group();
part.rotation.x = -Math.PI / 2;
part.add(rapids, cuts);
const geometry = new THREE.BufferGeometry();
geometry.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xffffff);
scene.add(part);
geometry.computeBoundingSphere();
const sphere = geometry.boundingSphere;
const radius = Math.max(sphere.radius, 1);
const axes = new THREE.AxesHelper(radius * 0.25);
part.add(axes);
const grid = new THREE.GridHelper(radius * 3, 15, 0xcccccc, 0xeeeeee);
grid.position.set(sphere.center.x, 0, -sphere.center.y);
scene.add(grid);

const view = document.getElementById("view");
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 100);
const center = new THREE.Vector3(sphere.center.x, sphere.center.z, -sphere.center.y);
camera.position.copy(center).add(new THREE.Vector3(radius * 1.6, radius * 1.4, radius * 2.2));
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(center);
controls.update();

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
         `${kinds[data.moves.kind[move]]} ${move + 1}\n${text}`;
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
document.documentElement.dataset.segments = segments;
document.documentElement.dataset.moves = moveCount;
document.documentElement.dataset.ready = "1";
