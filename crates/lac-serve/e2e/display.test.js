// What the page shows, in a real browser (as editor.test.js: Debian's headless Chromium and the
// real `lac serve`): a number field's text is what the curve uses, or says why not; messages
// leave the control points free; labels fit and do not overlap; the evolute, the drawable
// region and the comb stay meaningful in view; a path's curvature graph stays readable.
//
// Some checks read the page's modules (`import('/app/…')`: the same instances the page runs)
// and what it drew (pixels, and the boxes of the texts written on its canvases).

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startServer, startBrowser, openEditor as open, editorState, ARTIFACTS } from './harness.js';

let server;
let chrome;

before(async () => {
  server = await startServer();
  chrome = await startBrowser();
});

after(async () => {
  if (chrome) await chrome.close();
  if (server) await server.stop();
});

/** Every text written on a canvas, by canvas id, since its last full clear: {text, box: [x0,
 * y0, x1, y1] in CSS pixels} (installed before the page's scripts run). */
function recordTexts() {
  const texts = {};
  window.canvasTexts = texts;
  const proto = CanvasRenderingContext2D.prototype;
  const { clearRect, fillText } = proto;
  proto.clearRect = function (x, y, w, h) {
    const ratio = window.devicePixelRatio || 1;
    if (x <= 0 && y <= 0 && w * ratio >= this.canvas.width - 1 && h * ratio >= this.canvas.height - 1) texts[this.canvas.id] = [];
    return clearRect.call(this, x, y, w, h);
  };
  proto.fillText = function (text, x, y, ...rest) {
    const m = this.measureText(text);
    const t = this.getTransform();
    const ratio = window.devicePixelRatio || 1;
    const [a0, b0, a1, b1] = [x - m.actualBoundingBoxLeft, y - m.actualBoundingBoxAscent, x + m.actualBoundingBoxRight, y + m.actualBoundingBoxDescent];
    const pts = [[a0, b0], [a1, b0], [a0, b1], [a1, b1]].map(([a, b]) => t.transformPoint(new DOMPoint(a, b)));
    const xs = pts.map((p) => p.x / ratio);
    const ys = pts.map((p) => p.y / ratio);
    (texts[this.canvas.id] ||= []).push({ text: String(text), box: [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)] });
    return fillText.call(this, text, x, y, ...rest);
  };
}

const openEditor = (fragment = '', options = {}) => open(chrome.browser, server.url + fragment, { init: recordTexts, ...options });

/** Let the page settle: its update out and drawn, and (`region`) a region map that was asked. */
async function settle(page, { region = false } = {}) {
  await page.waitForTimeout(region ? 400 : 60);
  await page.waitForFunction(() => window.lacEditor.idle());
  await page.waitForTimeout(40);
}

async function shot(page, name) {
  await page.screenshot({ path: join(ARTIFACTS, `${name}.png`) });
}

/** Overlapping pairs (by more than half a pixel each way) among texts {text, box}. */
function overlaps(texts) {
  const out = [];
  texts.forEach((a, i) => texts.slice(i + 1).forEach((b) => {
    const [ax0, ay0, ax1, ay1] = a.box;
    const [bx0, by0, bx1, by1] = b.box;
    if (Math.min(ax1, bx1) - Math.max(ax0, bx0) > 0.5 && Math.min(ay1, by1) - Math.max(ay0, by0) > 0.5) out.push(`"${a.text}" and "${b.text}"`);
  }));
  return out;
}

test('number fields: text the curve cannot use is marked with why, and the curve keeps its last good value', async () => {
  const { page, context, errors } = await openEditor('#mode=compound');
  const field = page.locator('#param-alpha0');
  const type = async (locator, text) => {
    await locator.click({ clickCount: 3 });
    await locator.pressSequentially(text);
    await settle(page);
  };
  // A decimal comma is read as the decimal point, never as 15, and the note says so.
  await type(field, '1,5');
  assert.equal((await editorState(page)).design.alpha0, 1.5);
  assert.match(await page.locator('#note-param-alpha0').textContent(), /decimal comma: read as 1\.5/);
  // Leaving the field writes it with a point.
  await field.press('Tab');
  assert.equal(await field.inputValue(), '1.5');
  assert.ok(await page.locator('#note-param-alpha0').isHidden());
  // 1e400 is no number: typed key by key, the curve keeps 1e40, and the field says so.
  await type(field, '1e400');
  assert.equal((await editorState(page)).design.alpha0, 1e40);
  assert.equal(await field.getAttribute('aria-invalid'), 'true');
  const note = page.locator('#note-param-alpha0');
  assert.ok(await note.isVisible());
  assert.match(await note.textContent(), /α0: too large .*the curve keeps 1e\+40/);
  assert.equal(await field.getAttribute('title'), await note.textContent());
  await page.locator('#panel').screenshot({ path: join(ARTIFACTS, 'field-invalid.png') });
  // Out of its range: r_θ must be between 0 and 1.
  await type(page.locator('#param-ratio'), '1.5');
  assert.equal((await editorState(page)).design.ratio, 0.5);
  assert.equal(await page.locator('#param-ratio').getAttribute('aria-invalid'), 'true');
  assert.match(await page.locator('#note-param-ratio').textContent(), /out of range: must be > 0 and < 1; the curve keeps 0\.5/);
  // A point's field: two commas, and letters.
  const px = page.locator('[aria-label="P1 x"]');
  await type(px, '2,0,1');
  await type(page.locator('[aria-label="P1 y"]'), 'abc');
  const s = await editorState(page);
  assert.deepEqual(s.design.points[1], [2, 0]);
  assert.equal(await px.getAttribute('aria-invalid'), 'true');
  const pointNote = await page.locator('#note-point-1').textContent();
  assert.match(pointNote, /P1 x: not a number .*; the curve keeps 2/);
  assert.match(pointNote, /P1 y: not a number; the curve keeps 0/);
  // Text the curve uses again clears the mark; so does a value set elsewhere (the slider).
  await type(px, '2.25');
  assert.equal((await editorState(page)).design.points[1][0], 2.25);
  assert.equal(await px.getAttribute('aria-invalid'), null);
  assert.doesNotMatch(await page.locator('#note-point-1').textContent(), /P1 x/);
  await page.locator('[data-slider="alpha0"]').fill('-1');
  await settle(page);
  assert.equal(await field.inputValue(), '-1');
  assert.equal(await field.getAttribute('aria-invalid'), null);
  assert.ok(await note.isHidden());
  assert.deepEqual(errors, []);
  await context.close();
});

/** Each control point's element under it (in `views`, or the plane), as "view Pi: id". */
const underPoints = (page, views = [undefined]) => page.evaluate((names) => names.flatMap((name) =>
  window.lacEditor.state().design.points.map((_, i) => {
    const [x, y] = window.lacEditor.screenOf(i, name ?? undefined);
    return `${name || 'plane'} P${i}: ${document.elementFromPoint(x, y).id}`;
  })), views);

test('messages never cover a control point: in the plane the message moves aside, in space it sits in the perspective view', async () => {
  // A clothoid (α = −1) with P1 dragged to the top left: not drawable there.
  const { page, context, errors } = await openEditor('#mode=segment&points=-1,0;0,0.5;1,0&alpha=-1');
  const box = await page.locator('#plane').boundingBox();
  const [x1, y1] = await page.evaluate(() => window.lacEditor.screenOf(1));
  await page.mouse.move(x1, y1);
  await page.mouse.down();
  await page.mouse.move(box.x + 160, box.y + 40, { steps: 10 });
  await page.waitForFunction(() => window.lacEditor.idle() && window.lacEditor.state().stale);
  await settle(page);
  assert.ok(await page.locator('#message').isVisible());
  for (const under of await underPoints(page)) assert.match(under, /: plane$/, `while dragging, ${under}`);
  await page.mouse.up();
  await settle(page);
  assert.equal((await editorState(page)).error.kind, 'not_drawable');
  for (const under of await underPoints(page)) assert.match(under, /: plane$/, under);
  await shot(page, 'message-plane');
  await context.close();

  // No space segment found at this Ω (the default points at Ω = 10): the message leaves the
  // top, front and side views (where points are dragged) and their captions alone.
  const space = await openEditor('#mode=space&omega=10');
  assert.equal((await editorState(space.page)).error.kind, 'not_drawable');
  for (const under of await underPoints(space.page, ['top', 'front', 'side'])) assert.match(under, /: view-(top|front|side)$/, under);
  const rects = await space.page.evaluate(() => {
    const r = (el) => { const b = el.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
    return {
      message: r(document.getElementById('message')),
      others: ['top', 'front', 'side'].map((v) => r(document.getElementById(`view-${v}`).parentElement)),
      caption: r(document.querySelector('#view-3d + figcaption')),
    };
  });
  const meet = (a, b) => Math.min(a[2], b[2]) > Math.max(a[0], b[0]) && Math.min(a[3], b[3]) > Math.max(a[1], b[1]);
  for (const other of [...rects.others, rects.caption]) assert.ok(!meet(rects.message, other), `the message ${rects.message} meets ${other}`);
  await shot(space.page, 'message-space');
  assert.deepEqual([...errors, ...space.errors], []);
  await space.context.close();
});

test('space curve: the graphs\' labels fit without overlapping, and P0 and P1 have labels apart in the side view', async () => {
  const { page, context, errors } = await openEditor('#mode=space');
  const texts = await page.evaluate(() => window.canvasTexts);
  const size = await page.evaluate(() => Object.fromEntries(['lcg', 'kplot'].map((id) => [id, [document.getElementById(id).clientWidth, document.getElementById(id).clientHeight]])));
  for (const id of ['lcg', 'kplot']) {
    assert.deepEqual(overlaps(texts[id]), [], `texts of #${id} overlap`);
    const [w, h] = size[id];
    for (const { text, box } of texts[id]) assert.ok(box[0] >= 0 && box[1] >= 0 && box[2] <= w && box[3] <= h, `"${text}" leaves #${id}: ${box}`);
  }
  for (const view of ['3d', 'top', 'front', 'side']) {
    const labels = texts[`view-${view}`].filter((t) => /^P\d$/.test(t.text));
    assert.equal(labels.length, 4);
    assert.deepEqual(overlaps(labels), [], `labels of the ${view} view overlap`);
  }
  await page.locator('#lcg').screenshot({ path: join(ARTIFACTS, 'space-lcg.png') });
  await page.locator('#view-side').screenshot({ path: join(ARTIFACTS, 'space-side.png') });
  assert.deepEqual(errors, []);
  await context.close();
});

/** The canvas pixels (CSS pixel grid, device ratio 1) for which `kind` holds: 'evolute'
 * (its orange), 'tinted' (not a shade of grey: the region's shading). */
const pixels = (page, kind, where = null) => page.evaluate(([k, at]) => {
  const c = document.getElementById('plane');
  const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const is = (i) => {
    const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
    if (k === 'evolute') return r > 200 && g > 100 && g < 185 && b < 130 && r - b > 100;
    return Math.max(r, g, b) - Math.min(r, g, b) > 8;
  };
  if (at) return at.map(([x, y]) => is(4 * (Math.round(y) * c.width + Math.round(x))));
  const out = [];
  for (let y = 0; y < c.height; y += 2) for (let x = 0; x < c.width; x += 2) if (is(4 * (y * c.width + x))) out.push([x, y]);
  return out;
}, [kind, where]);

async function zoomOut(page, clicks) {
  const box = await page.locator('#plane').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let i = 0; i < clicks; i++) await page.mouse.wheel(0, 200);
  await settle(page);
  // Away from the curve, so that no hover mark is drawn.
  await page.mouse.move(box.x + 2, box.y + 2);
  await settle(page);
}

test('evolute: drawn in view, cut where |κ| is small, and said to be out of view when it is', async () => {
  // The default segment's evolute lies below the view: the page says so.
  const { page, context, errors } = await openEditor('#mode=segment');
  assert.equal((await pixels(page, 'evolute')).length, 0);
  const note = page.locator('#evolute-note');
  assert.ok(await note.isVisible(), 'no word that the evolute is out of view');
  assert.match(await note.textContent(), /out of view/);
  await zoomOut(page, 3);
  assert.ok((await pixels(page, 'evolute')).length > 20, 'zoomed out, the evolute shows');
  assert.ok(await note.isHidden());
  await context.close();

  // A path through an inflection, zoomed out: the evolute runs off to infinity where κ → 0,
  // and is drawn only where |κ| is at least a tenth of its largest, within 1/(0.1 κmax) of
  // the curve.
  const path = await openEditor('#mode=path');
  await zoomOut(path.page, 12);
  const far = await path.page.evaluate(async () => {
    const { state, view } = await import('/app/state.js');
    const rows = state.answer.samples;
    const kmax = Math.max(...rows.map((r) => Math.abs(r.kappa)));
    return { reach: view.scale / (0.1 * kmax), curve: rows.map((r) => view.toScreen([r.x, r.y])) };
  });
  const orange = await pixels(path.page, 'evolute');
  assert.ok(orange.length > 20, 'the evolute shows');
  const distance = Math.max(...orange.map(([x, y]) => Math.min(...far.curve.map(([cx, cy]) => Math.hypot(x - cx, y - cy)))));
  await path.page.locator('#plane').screenshot({ path: join(ARTIFACTS, 'evolute-path-zoomed-out.png') });
  assert.ok(distance <= far.reach + 8, `evolute drawn ${distance.toFixed(0)} px from the curve, beyond ${far.reach.toFixed(0)} px (|κ| < 0.1 κmax)`);
  assert.deepEqual([...errors, ...path.errors], []);
  await path.context.close();
});

test('segment: while dragging, the drawable region shades the whole visible canvas', async () => {
  const { page, context, errors } = await openEditor('#mode=segment&points=-1,0;0,0.5;1,0&alpha=-1');
  await zoomOut(page, 2);
  const box = await page.locator('#plane').boundingBox();
  const toWindow = async (p) => page.evaluate(async (q) => {
    const { view } = await import('/app/state.js');
    return view.toScreen(q);
  }, p).then(([x, y]) => [box.x + x, box.y + y]);
  const [x1, y1] = await page.evaluate(() => window.lacEditor.screenOf(1));
  await page.mouse.move(x1, y1);
  await page.mouse.down();
  // P1 above the square of its ends (where the region used to stop), where a curve exists.
  const [tx, ty] = await toWindow([-0.2, 1.3]);
  assert.ok(ty > box.y + 30, 'the target is in view');
  await page.mouse.move(tx, ty, { steps: 8 });
  await settle(page, { region: true });
  const s = await editorState(page);
  assert.equal(s.error, null);
  assert.ok(s.design.points[1][1] > 1.2, JSON.stringify(s.design.points[1]));
  const corners = [[6, 6], [box.width - 6, 6], [box.width - 6, box.height - 6], [box.width / 2, 6], [box.width / 2, box.height - 6]];
  const tinted = await pixels(page, 'tinted', corners);
  await shot(page, 'region-whole-canvas');
  assert.deepEqual(tinted, corners.map(() => true), `shading at ${JSON.stringify(corners)}`);
  // Beneath P1: green, it may go there.
  const green = await page.evaluate(([x, y]) => {
    const d = document.getElementById('plane').getContext('2d').getImageData(Math.round(x), Math.round(y), 1, 1).data;
    return d[1] > d[0] + 10 && d[1] > d[2] + 5;
  }, [tx - box.x, ty - box.y + 22]);
  assert.ok(green, 'no green beneath P1');
  await page.mouse.up();
  assert.deepEqual(errors, []);
  await context.close();
});

test('segment: dragging toward a hook keeps the comb\'s teeth in view', async () => {
  const { page, context, errors } = await openEditor('#mode=segment');
  const [x1, y1] = await page.evaluate(() => window.lacEditor.screenOf(1));
  const [x2, y2] = await page.evaluate(() => window.lacEditor.screenOf(2));
  await page.mouse.move(x1, y1);
  await page.mouse.down();
  const box = await page.locator('#plane').boundingBox();
  let worst = null;
  for (let i = 1; i <= 16; i++) {
    await page.mouse.move(x1 + (x2 - x1) * 0.9 * i / 16, y1 + (y2 - 40 - y1) * i / 16);
    await settle(page);
    // Teeth of the samples at least 24 pixels inside the canvas end in it.
    const out = await page.evaluate(async ([w, h]) => {
      const { state, view } = await import('/app/state.js');
      if (state.error) return null;
      const bad = [];
      for (const r of state.answer.samples) {
        const [x, y] = view.toScreen([r.x, r.y]);
        if (x < 24 || y < 24 || x > w - 24 || y > h - 24) continue;
        const tip = view.toScreen([r.x + Math.sin(r.theta) * r.kappa * state.combScale, r.y - Math.cos(r.theta) * r.kappa * state.combScale]);
        if (tip[0] < 0 || tip[1] < 0 || tip[0] > w || tip[1] > h) bad.push(tip.map(Math.round));
      }
      return bad;
    }, [box.width, box.height]);
    if (out && out.length) worst = worst || { step: i, tips: out.slice(0, 3) };
  }
  await shot(page, 'comb-toward-hook');
  const kEnd = Math.abs((await editorState(page)).answer.curvature_end);
  assert.ok(kEnd > 5, `not a hook yet: κ end ${kEnd}`);
  assert.equal(worst, null, `teeth off the canvas while dragging: ${JSON.stringify(worst)}`);
  await page.mouse.up();
  assert.deepEqual(errors, []);
  await context.close();
});

test('path: every segment\'s line in the logarithmic curvature graph is readable', async () => {
  const { page, context, errors } = await openEditor('#mode=path');
  // The graph's options as the page draws them: each segment's line spans a fair share of
  // the graph's width (an inflection's κ → 0 would stretch ln ρ to 28 and more).
  const shares = await page.evaluate(async () => {
    const { MODES } = await import('/app/modes/index.js');
    const { state } = await import('/app/state.js');
    const { series } = MODES.path.plots(state.answer, { hover: null, error: null }).lcg;
    const xs = series.flatMap((s) => s.points.map(([x]) => x));
    const width = Math.max(...xs) - Math.min(...xs);
    return series.map((s) => Math.abs(s.points[s.points.length - 1][0] - s.points[0][0]) / width);
  });
  assert.equal(shares.length, 4);
  for (const share of shares) assert.ok(share >= 0.15, `a segment's line spans ${(100 * share).toFixed(1)}% of the graph`);
  await page.locator('#lcg').scrollIntoViewIfNeeded();
  await page.locator('#lcg').screenshot({ path: join(ARTIFACTS, 'path-lcg.png') });
  assert.deepEqual(errors, []);
  await context.close();
});
