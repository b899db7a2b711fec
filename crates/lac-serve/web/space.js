// The space-curve views: a perspective view that orbits when dragged, and the three
// orthographic views (top x–y, front x–z, side y–z) in which the control points are dragged.

import { View } from './view.js';
import { prepare } from './plots.js';
import { COLORS, evoluteKept } from './draw.js';
import { labelPlaces, inBox, combRoom } from './layout.js';

/** Which coordinates each orthographic view shows, across and up. */
const AXES = { top: [0, 1], front: [0, 2], side: [1, 2] };

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];

/** The tips of the curvature comb's teeth: from each sample away from the centre of
 * curvature, κ × `scale` long. */
export function combTips(samples, scale) {
  return samples.map((r) => [
    r.x - r.n[0] * r.kappa * scale,
    r.y - r.n[1] * r.kappa * scale,
    r.z - r.n[2] * r.kappa * scale,
  ]);
}

/** Drawing and dragging in the four views of a space curve. */
export class SpaceViews {
  /**
   * `canvases`: {'3d', top, front, side}; `on`: {drag(index, point), dragEnd(), hover(sample,
   * clientX, clientY) with sample null when none is near}.
   */
  constructor(canvases, on) {
    this.canvases = canvases;
    this.on = on;
    this.yaw = -0.5;
    this.pitch = 0.6;
    this.views = { top: new View(), front: new View(), side: new View() };
    this.scene = null;
    this.drag = null;
    this.inset = 0; // pixels at the top of the perspective view taken by the message
    for (const [name, canvas] of Object.entries(canvases)) this.listen(name, canvas);
  }

  /** Fit the orthographic views (one scale for all three) to `points` (the control points,
   * and the curve and its comb once drawn). */
  fit(points) {
    const lo = [0, 1, 2].map((i) => Math.min(...points.map((p) => p[i])));
    const hi = [0, 1, 2].map((i) => Math.max(...points.map((p) => p[i])));
    let scale = Infinity;
    for (const [name, [a, b]] of Object.entries(AXES)) {
      const c = this.canvases[name];
      const v = this.views[name];
      v.fit([lo[a], hi[a], lo[b], hi[b]], c.clientWidth || 300, c.clientHeight || 200, 28);
      scale = Math.min(scale, v.scale);
    }
    for (const [name, [a, b]] of Object.entries(AXES)) {
      const c = this.canvases[name];
      const v = this.views[name];
      v.scale = scale;
      v.ox = (c.clientWidth || 300) / 2 - scale * (lo[a] + hi[a]) / 2;
      v.oy = (c.clientHeight || 200) / 2 + scale * (lo[b] + hi[b]) / 2;
    }
    this.center = [0, 1, 2].map((i) => (lo[i] + hi[i]) / 2);
    this.radius = Math.max(0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]), 1e-9);
  }

  /** The perspective projection of `p` in a `w` × `h` canvas: [x, y, depth]. */
  project(p, w, h) {
    const [x, y, z] = sub(p, this.center);
    const cy = Math.cos(this.yaw), sy = Math.sin(this.yaw);
    const cp = Math.cos(this.pitch), sp = Math.sin(this.pitch);
    // Turn about z by the yaw, then tilt about the screen's x axis by the pitch, so that a
    // positive pitch looks down on the x–y plane; Y is the depth.
    const X = cy * x - sy * y;
    const Y0 = sy * x + cy * y;
    const Y = cp * Y0 - sp * z;
    const Z = sp * Y0 + cp * z;
    const distance = 3.2 * this.radius;
    const focal = (0.55 * Math.min(w, h) * distance) / this.radius;
    const k = focal / (distance + Y);
    return [w / 2 + k * X, h / 2 - k * Z, Y];
  }

  /** The perspective view's projection of `p` in its `w` × `h` canvas, below the inset. */
  perspective(p, w, h) {
    const [x, y, depth] = this.project(p, w, h - this.inset);
    return [x, y + this.inset, depth];
  }

  /** The message takes `pixels` at the top of the perspective view: draw it below them. */
  setInset(pixels) {
    if (pixels === this.inset) return;
    this.inset = pixels;
    this.drawView('3d');
  }

  /**
   * Draw {points, samples: [{s, x, y, z, kappa, tau, n}], stale, show, combScale, active,
   * hover}.
   */
  draw(scene) {
    this.scene = scene;
    const told = Object.keys(this.canvases).map((name) => this.drawView(name));
    const evolute = told.includes('visible') ? 'visible' : told.includes('outside') ? 'outside' : 'off';
    return { evolute };
  }

  /** Draw view `name`; returns what it shows of the evolute ('off', 'visible', 'outside'). */
  drawView(name) {
    const scene = this.scene;
    if (!scene || !this.center) return 'off';
    let evolute = 'off';
    const { ctx, width, height } = prepare(this.canvases[name]);
    const to = name === '3d'
      ? (p) => this.perspective(p, width, height)
      : (p) => this.views[name].toScreen([p[AXES[name][0]], p[AXES[name][1]]]);
    const line = (points) => {
      ctx.beginPath();
      points.forEach((p, i) => {
        const [x, y] = to(p);
        if (i) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      });
      ctx.stroke();
    };
    const curve = (scene.samples || []).map((r) => [r.x, r.y, r.z]);
    if (name === '3d') this.floor(ctx, to, curve.length ? curve : scene.points);
    if (curve.length) {
      if (scene.stale) {
        ctx.strokeStyle = COLORS.faint;
        ctx.setLineDash([6, 4]);
        ctx.lineWidth = 2;
        line(curve);
        ctx.setLineDash([]);
      } else {
        if (scene.show.evolute) {
          // Centres of curvature P + N/κ, cut where κ is small (draw.js), in view.
          const kmax = scene.samples.reduce((m, r) => Math.max(m, Math.abs(r.kappa)), 0);
          const runs = [];
          let run = [];
          for (const r of scene.samples) {
            const rho = 1 / r.kappa;
            const q = evoluteKept(r, kmax) ? to([r.x + r.n[0] * rho, r.y + r.n[1] * rho, r.z + r.n[2] * rho]) : null;
            // In perspective, not what lies behind the eye (3.2 radii from the centre).
            if (q && !(q[2] < -3 * this.radius)) run.push(q);
            else {
              if (run.length > 1) runs.push(run);
              run = [];
            }
          }
          if (run.length > 1) runs.push(run);
          const drawn = inBox(runs, [-50, width + 50, -50, height + 50]);
          if (runs.length) evolute = inBox(drawn, [0, width, 0, height]).length ? 'visible' : 'outside';
          ctx.strokeStyle = COLORS.evolute;
          ctx.lineWidth = 1.2;
          ctx.setLineDash([5, 3]);
          for (const part of drawn) {
            ctx.beginPath();
            part.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
            ctx.stroke();
          }
          ctx.setLineDash([]);
        }
        if (scene.show.comb) {
          const tips = combTips(scene.samples, scene.combScale);
          ctx.strokeStyle = COLORS.comb;
          ctx.lineWidth = 1;
          ctx.beginPath();
          const every = Math.max(1, Math.round(curve.length / 96));
          curve.forEach((p, i) => {
            if (i % every && i !== curve.length - 1) return;
            const a = to(p);
            const b = to(tips[i]);
            ctx.moveTo(a[0], a[1]);
            ctx.lineTo(b[0], b[1]);
          });
          ctx.stroke();
          ctx.strokeStyle = COLORS.combEdge;
          line(tips);
        }
        ctx.strokeStyle = COLORS.curve;
        ctx.lineWidth = 2.2;
        line(curve);
      }
    }
    if (scene.show.polygon || scene.stale) {
      ctx.strokeStyle = COLORS.polygon;
      ctx.lineWidth = 1;
      line(scene.points);
    }
    const onScreen = scene.points.map(to);
    ctx.font = '11px system-ui, sans-serif';
    const labels = labelPlaces(ctx, onScreen, onScreen.map((_, i) => `P${i}`), 8, [width, height]);
    onScreen.forEach(([x, y], i) => {
      ctx.beginPath();
      ctx.arc(x, y, i === scene.active ? 7.5 : 6, 0, 2 * Math.PI);
      ctx.fillStyle = i === scene.active ? '#ffe08a' : '#fff';
      ctx.fill();
      ctx.strokeStyle = scene.stale ? COLORS.bad : '#333';
      ctx.lineWidth = 1.5;
      ctx.stroke();
      ctx.fillStyle = '#333';
      ctx.fillText(`P${i}`, labels[i][0], labels[i][1]);
    });
    if (scene.hover) {
      const [x, y] = to([scene.hover.x, scene.hover.y, scene.hover.z]);
      ctx.strokeStyle = '#d0342c';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(x, y, 5, 0, 2 * Math.PI);
      ctx.stroke();
    }
    return evolute;
  }

  /** The perspective view's floor: the curve's shadow and the x, y, z axes at the box's
   * lowest corner. */
  floor(ctx, to, points) {
    const zmin = Math.min(...this.scene.points.map((p) => p[2]), ...points.map((p) => p[2]));
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.12)';
    ctx.lineWidth = 3;
    ctx.beginPath();
    points.forEach((p, i) => {
      const [x, y] = to([p[0], p[1], zmin]);
      if (i) ctx.lineTo(x, y); else ctx.moveTo(x, y);
    });
    ctx.stroke();
    const r = this.radius * 0.3;
    const o = [0, 1].map((i) => Math.min(...points.map((p) => p[i])));
    o.push(zmin);
    [['x', '#c62828', [r, 0, 0]], ['y', '#2e7d32', [0, r, 0]], ['z', '#1565c0', [0, 0, r]]].forEach(([label, color, d]) => {
      const a = to(o);
      const b = to([o[0] + d[0], o[1] + d[1], o[2] + d[2]]);
      ctx.strokeStyle = color;
      ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.stroke();
      ctx.fillStyle = color;
      ctx.font = '11px system-ui, sans-serif';
      ctx.fillText(label, b[0] + 3, b[1] - 3);
    });
  }

  /** The largest comb scale at which the teeth of `samples` stay in the top, front and side
   * views (layout.js). */
  combLimit(samples) {
    let room = Infinity;
    for (const [name, [a, b]] of Object.entries(AXES)) {
      const v = this.views[name];
      const c = this.canvases[name];
      const teeth = samples.map((r) => {
        const p = [r.x, r.y, r.z];
        return [v.toScreen([p[a], p[b]]), [-r.n[a] * r.kappa * v.scale, r.n[b] * r.kappa * v.scale]];
      });
      room = Math.min(room, combRoom(teeth, c.clientWidth, c.clientHeight));
    }
    return room;
  }

  /** Index of the control point within `radius` pixels of (sx, sy) in view `name`. */
  hit(name, sx, sy, radius) {
    if (!this.scene) return null;
    let best = null;
    let bestDistance = radius;
    this.scene.points.forEach((p, i) => {
      const [x, y] = this.views[name].toScreen([p[AXES[name][0]], p[AXES[name][1]]]);
      const d = Math.hypot(x - sx, y - sy);
      if (d <= bestDistance) { best = i; bestDistance = d; }
    });
    return best;
  }

  /** The sample nearest (sx, sy) in view `name`, within 16 pixels. */
  nearest(name, sx, sy) {
    const samples = (this.scene && !this.scene.stale && this.scene.samples) || [];
    let best = null;
    let bestDistance = 16;
    for (const r of samples) {
      const [x, y] = name === '3d'
        ? this.perspective([r.x, r.y, r.z], this.canvases[name].clientWidth, this.canvases[name].clientHeight)
        : this.views[name].toScreen([[r.x, r.y, r.z][AXES[name][0]], [r.x, r.y, r.z][AXES[name][1]]]);
      const d = Math.hypot(x - sx, y - sy);
      if (d < bestDistance) { best = r; bestDistance = d; }
    }
    return best;
  }

  listen(name, canvas) {
    canvas.addEventListener('pointerdown', (e) => {
      canvas.setPointerCapture(e.pointerId);
      const index = name === '3d' ? null : this.hit(name, e.offsetX, e.offsetY, e.pointerType === 'touch' ? 22 : 12);
      this.drag = { name, index, pointerId: e.pointerId, x: e.clientX, y: e.clientY };
      if (index !== null) this.on.drag(index, null, e.timeStamp);
      e.preventDefault();
    });
    canvas.addEventListener('pointermove', (e) => {
      const drag = this.drag;
      if (!drag || drag.pointerId !== e.pointerId) {
        const sample = this.nearest(name, e.offsetX, e.offsetY);
        this.on.hover(sample, e.clientX, e.clientY);
        return;
      }
      if (drag.index === null) {
        if (name !== '3d') return;
        this.yaw += (e.clientX - drag.x) * 0.01;
        this.pitch = Math.max(-1.5, Math.min(1.5, this.pitch + (e.clientY - drag.y) * 0.01));
        drag.x = e.clientX;
        drag.y = e.clientY;
        this.drawView('3d');
        return;
      }
      const [u, v] = this.views[name].toWorld([e.offsetX, e.offsetY]);
      const point = this.scene.points[drag.index].slice();
      point[AXES[name][0]] = u;
      point[AXES[name][1]] = v;
      this.on.drag(drag.index, point, e.timeStamp, this.views[name].scale);
    });
    const end = (e) => {
      if (!this.drag || this.drag.pointerId !== e.pointerId) return;
      const wasPoint = this.drag.index !== null;
      this.drag = null;
      if (wasPoint) this.on.dragEnd();
    };
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
    canvas.addEventListener('pointerleave', () => this.on.hover(null));
  }

  /** Screen position of control point `index` in view `name` (for tests and touch aids). */
  screenOf(name, index) {
    const p = this.scene.points[index];
    return this.views[name].toScreen([p[AXES[name][0]], p[AXES[name][1]]]);
  }
}
