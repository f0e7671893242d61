// The 3D tool-path viewer (three.js): rapids dashed, feeds coloured by
// tool, orbit/pan/zoom, the standard views, a click on a move names its
// source line, a line's moves can be highlighted, and the cut can be
// replayed up to a time of the program.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { Kind, type Toolpath } from './toolpath';

// Distinct on a dark background and for the common colour blindnesses first.
const PALETTE = [0x4fc3f7, 0xffb74d, 0x81c784, 0xe57373, 0xba68c8, 0xfff176, 0x4db6ac, 0xf06292];

export function toolColour(tool: number): number {
  return PALETTE[tool % PALETTE.length];
}

export type View = 'top' | 'front' | 'side' | 'iso';

export class Viewer {
  readonly canvas: HTMLCanvasElement;
  private renderer: THREE.WebGLRenderer;
  private scene = new THREE.Scene();
  private camera: THREE.PerspectiveCamera;
  private controls: OrbitControls;
  private path: Toolpath | null = null;
  private pickables: THREE.LineSegments[] = [];
  private segmentVertex = new Map<THREE.Object3D, Uint32Array>();
  private highlight: THREE.LineSegments | null = null;
  private drawn: { lines: THREE.LineSegments; vertex: Uint32Array }[] = [];
  private tool: THREE.Group | null = null; // the replay's tool and the move it is on
  private stock: THREE.Object3D | null = null;
  private centre = new THREE.Vector3();
  private size = 1;
  onPick: (line: number) => void = () => {};

  constructor(host: HTMLElement) {
    this.canvas = document.createElement('canvas');
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute(
      'aria-label',
      '3D tool path: drag to orbit, right-drag or arrow keys to pan, wheel to zoom; click a move to find its line',
    );
    host.append(this.canvas);
    // preserveDrawingBuffer: the picture can be read back (tests, screenshots).
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    this.scene.background = new THREE.Color(0x1d232a);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1e6);
    this.camera.up.set(0, 0, 1); // the machine's Z is up
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.listenToKeyEvents(this.canvas);
    this.controls.addEventListener('change', () => this.render());
    new ResizeObserver(() => this.resize()).observe(host);
    this.canvas.addEventListener('click', (e) => this.pick(e));
    this.resize();
  }

  load(path: Toolpath): void {
    this.path = path;
    this.scene.clear();
    this.pickables = [];
    this.drawn = [];
    this.tool = null;
    this.segmentVertex.clear();
    const [rapids, cuts] = this.segments(path);
    const dashed = new THREE.LineDashedMaterial({ color: 0x9aa5b1, dashSize: 1, gapSize: 1 });
    const rapidLines = new THREE.LineSegments(rapids.geometry, dashed);
    rapidLines.computeLineDistances();
    const cutLines = new THREE.LineSegments(
      cuts.geometry,
      new THREE.LineBasicMaterial({ vertexColors: true }),
    );
    for (const [obj, map] of [
      [rapidLines, rapids.vertex],
      [cutLines, cuts.vertex],
    ] as const) {
      this.scene.add(obj);
      this.pickables.push(obj);
      this.segmentVertex.set(obj, map);
      this.drawn.push({ lines: obj, vertex: map });
    }
    const min = new THREE.Vector3(...path.min);
    const max = new THREE.Vector3(...path.max);
    this.centre = min.clone().add(max).multiplyScalar(0.5);
    this.size = Math.max(max.clone().sub(min).length(), 1);
    dashed.dashSize = dashed.gapSize = this.size / 150;
    this.scene.add(new THREE.AxesHelper(this.size / 8));
    if (this.stock) this.scene.add(this.stock);
    this.setView('iso');
  }

  // The stock's mesh (stock.ts) shown with the path, or none.
  setStock(object: THREE.Object3D | null): void {
    if (this.stock) this.scene.remove(this.stock);
    this.stock = object;
    if (object) this.scene.add(object);
    this.render();
  }

  // The tool path shown or hidden (the stock alone).
  showPath(visible: boolean): void {
    for (const o of this.pickables) o.visible = visible;
    this.render();
  }

  // The segments i-1 → i of every vertex, split into rapids and the rest,
  // written straight into typed arrays (a million-move program's picture).
  private segments(p: Toolpath) {
    let rapids = 0;
    for (let i = 1; i < p.count; i++) if (p.kinds[i] === Kind.Rapid) rapids++;
    const cuts = Math.max(p.count - 1, 0) - rapids;
    const rapidXyz = new Float32Array(rapids * 6);
    const cutXyz = new Float32Array(cuts * 6);
    const colours = new Float32Array(cuts * 6);
    const rapidVertex = new Uint32Array(rapids);
    const cutVertex = new Uint32Array(cuts);
    const c = new THREE.Color();
    let r = 0;
    let k = 0;
    for (let i = 1; i < p.count; i++) {
      const segment = p.positions.subarray((i - 1) * 3, i * 3 + 3);
      if (p.kinds[i] === Kind.Rapid) {
        rapidXyz.set(segment, r * 6);
        rapidVertex[r++] = i;
      } else {
        cutXyz.set(segment, k * 6);
        c.setHex(toolColour(p.tools[i]));
        for (let j = 0; j < 2; j++) colours.set([c.r, c.g, c.b], k * 6 + j * 3);
        cutVertex[k++] = i;
      }
    }
    const geometry = (xyz: Float32Array) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
      return g;
    };
    const cutGeometry = geometry(cutXyz);
    cutGeometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    return [
      { geometry: geometry(rapidXyz), vertex: rapidVertex },
      { geometry: cutGeometry, vertex: cutVertex },
    ] as const;
  }

  // The cut up to `seconds` of the program: the moves that ended before it
  // drawn, the one under way drawn to where the tool is, the tool shown
  // there. Returns the vertex that move ends at (0 before the first move).
  replayTo(seconds: number): { vertex: number; at: THREE.Vector3 } {
    const p = this.path;
    if (!p || p.count < 2) return { vertex: 0, at: new THREE.Vector3() };
    const i = firstAtOrAfter(p.times, seconds, p.count);
    const end = Math.min(Math.max(i, 1), p.count - 1);
    const from = new THREE.Vector3().fromArray(p.positions, (end - 1) * 3);
    const to = new THREE.Vector3().fromArray(p.positions, end * 3);
    const span = p.times[end] - p.times[end - 1];
    const f = i === 0 ? 0 : span > 0 ? Math.min(Math.max((seconds - p.times[end - 1]) / span, 0), 1) : 1;
    const at = from.clone().lerp(to, f);
    // Segments are stored by the vertex that ends them, in the program's order.
    for (const d of this.drawn) d.lines.geometry.setDrawRange(0, 2 * firstAtOrAfter(d.vertex, end, d.vertex.length));
    this.showTool(from, at, p.kinds[end] === Kind.Rapid ? 0x9aa5b1 : toolColour(p.tools[end]));
    this.render();
    return { vertex: end, at };
  }

  // The whole path again, without the tool.
  endReplay(): void {
    for (const d of this.drawn) d.lines.geometry.setDrawRange(0, Infinity);
    if (this.tool) this.scene.remove(this.tool);
    this.tool = null;
    this.render();
  }

  private showTool(from: THREE.Vector3, at: THREE.Vector3, colour: number): void {
    if (this.tool) this.scene.remove(this.tool);
    const g = new THREE.BufferGeometry().setFromPoints([from, at]);
    const move = new THREE.Line(g, new THREE.LineBasicMaterial({ color: colour }));
    const tip = new THREE.Mesh(new THREE.SphereGeometry(this.size / 120, 16, 8), new THREE.MeshBasicMaterial({ color: 0xffffff }));
    tip.position.copy(at);
    this.tool = new THREE.Group().add(move, tip);
    this.scene.add(this.tool);
  }

  setView(view: View): void {
    const d = this.size * 1.15;
    const dir = {
      top: new THREE.Vector3(0, -1e-4, 1),
      front: new THREE.Vector3(0, -1, 0),
      side: new THREE.Vector3(1, 0, 0),
      iso: new THREE.Vector3(1, -1, 1),
    }[view].normalize();
    this.camera.position.copy(this.centre).addScaledVector(dir, d);
    this.camera.near = this.size / 1000;
    this.camera.far = this.size * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(this.centre);
    this.controls.update();
    this.render();
  }

  // Shows the moves of source line `line` in white, over the rest.
  highlightLine(line: number): number {
    if (this.highlight) this.scene.remove(this.highlight);
    this.highlight = null;
    const p = this.path;
    if (!p) return 0;
    const xyz: number[] = [];
    for (let i = 1; i < p.count; i++) {
      if (p.lines[i] !== line) continue;
      xyz.push(...p.positions.subarray((i - 1) * 3, i * 3), ...p.positions.subarray(i * 3, i * 3 + 3));
    }
    if (xyz.length) {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute(xyz, 3));
      this.highlight = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0xffffff, depthTest: false }));
      this.highlight.renderOrder = 1;
      this.scene.add(this.highlight);
    }
    this.render();
    return xyz.length / 6;
  }

  private pick(e: MouseEvent): void {
    const p = this.path;
    if (!p) return;
    const r = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.params.Line = { threshold: this.camera.position.distanceTo(this.controls.target) / 150 };
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObjects(this.pickables.filter((o) => o.visible), false)[0];
    if (!hit || hit.index === undefined) return;
    const vertex = this.segmentVertex.get(hit.object)?.[Math.floor(hit.index / 2)];
    if (vertex !== undefined) this.onPick(p.lines[vertex]);
  }

  private resize(): void {
    const w = this.canvas.parentElement?.clientWidth || 600;
    const hgt = Math.max(240, Math.round(w * 0.6));
    this.renderer.setSize(w, hgt, false);
    this.camera.aspect = w / hgt;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render(): void {
    this.renderer.render(this.scene, this.camera);
  }
}

// The first index of ascending `a` (its first `n`) whose value is at least `x`; `n` when none.
function firstAtOrAfter(a: ArrayLike<number>, x: number, n: number): number {
  let lo = 0;
  let hi = n;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (a[mid] < x) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}
