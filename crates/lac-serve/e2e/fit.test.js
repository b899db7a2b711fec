// The Fit mode in a real browser: 200 points of a circular arc with tiny noise pasted in, the
// fit drawn with its points coloured by their distance, the tolerance slider dragged with the
// fit following, and the fit exported for CAD. The screenshot goes to $LAC_ARTIFACTS.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { startServer, startBrowser, servePage, ARTIFACTS } from './harness.js';

let server;
let chrome;

before(async () => {
  server = await startServer();
  chrome = await startBrowser();
});

after(async () => {
  console.log(`screenshots in ${ARTIFACTS}`);
  if (chrome) await chrome.close();
  if (server) await server.stop();
});

/** 200 points on three quarters of a circle of radius 2, each moved along the radius by
 * up to 1e-4 of it (2e-4). */
function arcPoints(n = 200, noise = 1e-4) {
  const points = [];
  for (let k = 0; k < n; k++) {
    const t = (1.5 * Math.PI * k) / (n - 1);
    const r = 2 * (1 + noise * Math.sin(1.7 * k));
    points.push([r * Math.cos(t), r * Math.sin(t)]);
  }
  return points;
}

const editorState = (page) => page.evaluate(() => window.lacEditor.state());

/** Wait until the page has drawn an answer newer than `updates` and has nothing in flight. */
async function settled(page, updates) {
  await page.waitForFunction((n) => window.lacEditor.probe.updates > n && window.lacEditor.idle(), updates);
}

const updates = (page) => page.evaluate(() => window.lacEditor.probe.updates);

/** The readout's value of `key`. */
const readout = (page, key) => page.getAttribute(`#readout dd[data-key="${key}"]`, 'data-value');

/** Pixels of the plane canvas in the colour [r, g, b] (within 8 per channel). */
const pixels = (page, color) => page.evaluate(([r, g, b]) => {
  const c = document.getElementById('plane');
  const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (Math.abs(data[i] - r) <= 8 && Math.abs(data[i + 1] - g) <= 8 && Math.abs(data[i + 2] - b) <= 8) n += 1;
  }
  return n;
}, color);

test('fit: pasted points of an arc are fitted within the tolerance, coloured, followed by the slider, exported', async () => {
  const context = await chrome.browser.newContext({ viewport: { width: 1280, height: 800 } });
  await servePage(context);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => {
    if (m.type() === 'error' && !/status of 4\d\d/.test(m.text())) errors.push(m.text());
  });
  await page.goto(server.url);
  await page.waitForFunction(() => window.lacEditor && window.lacEditor.probe.updates >= 1 && window.lacEditor.idle());

  let n = await updates(page);
  await page.click('#modes button[data-mode="fit"]');
  await settled(page, n);
  assert.equal((await editorState(page)).mode, 'fit');

  // Paste: "x y" lines.
  const points = arcPoints();
  await page.fill('#fit-points', points.map(([x, y]) => `${x} ${y}`).join('\n'));
  n = await updates(page);
  await page.click('#fit-apply');
  await settled(page, n);
  let state = await editorState(page);
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.equal(state.design.points.length, 200);
  assert.deepEqual(state.design.points, points, 'the text is read to the same doubles');
  const tolerance = state.design.tolerance;
  assert.equal(Number(await readout(page, 'point_count')), 200);
  const maxDistance = Number(await readout(page, 'max_distance'));
  assert.ok(maxDistance <= tolerance, `largest distance ${maxDistance} > tolerance ${tolerance}`);
  assert.equal(state.answer.distances.length, 200);
  assert.ok(Number(await readout(page, 'fitted_segments')) >= 1);
  // A circle: one segment, α anything (the curvature is constant), radius 2.
  assert.ok(state.answer.samples.every((r) => Math.abs(r.kappa - 0.5) < 1e-3), 'κ = 1/2 along the fit');
  assert.match(await page.textContent('#readout dd[data-key="max_distance"]'), /at point \d+ \(≤ tolerance\)/);

  // The drawing: the fitted path (dark), and the points green (all within half the tolerance).
  const NEAR = await page.evaluate(async () => (await import('/app/modes/fit.js')).NEAR);
  await page.screenshot({ path: join(ARTIFACTS, 'fit.png') });
  const dark = await pixels(page, [27, 27, 27]);
  const green = await pixels(page, NEAR);
  // The path shows between the points (2.2 px dots about 5 px apart on it).
  assert.ok(dark > 100, `the fitted path is drawn (${dark} dark pixels)`);
  assert.ok(green > 500, `the points are drawn in green (${green} green pixels)`);

  // Drag the tolerance slider (log10, steps of 0.01) down to 10^-3.5 = 3.16e-4 in 12 steps: the fit follows, each answer for the
  // tolerance of its moment (the page folds moves made while a request is out into the next).
  const from = Math.log10(tolerance);
  const to = -3.5;
  const tight = 3.16e-4;
  n = await updates(page);
  for (let k = 1; k <= 12; k++) {
    await page.evaluate((v) => {
      const range = document.querySelector('[data-slider="tolerance"]');
      range.value = String(v);
      range.dispatchEvent(new Event('input', { bubbles: true }));
    }, from + ((to - from) * k) / 12);
    await page.waitForTimeout(15);
  }
  await page.evaluate(() => document.querySelector('[data-slider="tolerance"]').dispatchEvent(new Event('change', { bubbles: true })));
  await settled(page, n);
  await page.waitForFunction(() => window.lacEditor.idle());
  state = await editorState(page);
  assert.equal(state.design.tolerance, tight);
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.equal(state.answer.tolerance, tight, 'the answer drawn is the last tolerance\'s');
  assert.ok(state.answer.max_distance <= tight);
  assert.ok((await updates(page)) - n >= 2, 'the fit followed the drag');
  // Now the noise (up to 2e-4) is near the tolerance: the points' colours differ.
  const colours = await page.evaluate(async () => {
    const m = await import('/app/modes/fit.js');
    const { answer, design } = window.lacEditor.state();
    return answer.distances.map((d) => m.distanceColor(d / design.tolerance).join(','));
  });
  assert.ok(new Set(colours).size > 1, 'the colours follow the distances');
  await page.screenshot({ path: join(ARTIFACTS, 'fit-tight.png') });

  // CAD: the fit's result, placed again by the server, within 1e-6; of the first design (the
  // points of a logarithmic spiral: the near-circle fits above, α ≈ 8, fail in lac-export's
  // B-spline fit, a numerical failure of its own to report).
  n = await updates(page);
  await page.click('#reset');
  await settled(page, n);
  const download = page.waitForEvent('download');
  await page.selectOption('#export-cad', 'json');
  const file = await Promise.race([download, page.waitForSelector('#toast:not([hidden])').then(async () => {
    throw new Error(`no download: ${await page.textContent('#toast')}`);
  })]);
  assert.equal(file.suggestedFilename(), 'lac-fit.json');
  const nurbs = JSON.parse(readFileSync(await file.path(), 'utf8'));
  assert.equal(nurbs.kind, 'fit');
  assert.ok(nurbs.max_deviation <= 1e-6);

  await context.close();
  assert.deepEqual(errors, []);
});
