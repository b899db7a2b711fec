// The editor in a real browser: Debian's headless Chromium, driven by playwright-core, against
// the real `lac serve` binary on a free port of 127.0.0.1.
//
// In every mode a control point is dragged along a scripted path of at least 200 steps; each
// step waits for the page to draw the answer of its move, and the page's own measure of that
// update (input event to the end of the redraw: request, solve, response, redraw) is collected
// and printed as a median and 95th percentile. After the drag, the numbers the page shows are
// compared with what the `lac` command prints for the same design, bit for bit. Screenshots go
// to $LAC_ARTIFACTS (or a temporary directory), which is printed.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { writeFileSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { startServer, startBrowser, openEditor as open, editorState, settled, LAC_BIN, ARTIFACTS } from './harness.js';

const STEPS = 220;
const SAMPLES = 257;

let server;
let chrome;
const latency = {};

before(async () => {
  server = await startServer();
  chrome = await startBrowser();
});

after(async () => {
  const stats = (ms) => {
    const sorted = [...ms].sort((a, b) => a - b);
    const at = (p) => sorted[Math.min(sorted.length - 1, Math.round((sorted.length - 1) * p))];
    return `median ${at(0.5).toFixed(1).padStart(5)} ms  p95 ${at(0.95).toFixed(1).padStart(5)} ms`;
  };
  const lines = Object.entries(latency).map(([mode, { event, work }]) =>
    `${mode.padEnd(10)} ${String(work.length).padStart(4)} updates   update (request, solve, response, redraw): ${stats(work)}   from the input event: ${stats(event)}`);
  const report = ['drag-update latency, measured in the page over a scripted drag:', ...lines].join('\n');
  console.log(report);
  writeFileSync(join(ARTIFACTS, 'latency.txt'), report + '\n');
  console.log(`screenshots and figures in ${ARTIFACTS}`);
  if (chrome) await chrome.close();
  if (server) await server.stop();
});

/** The `lac` command's JSON for `args`. */
function lac(...args) {
  return JSON.parse(execFileSync(LAC_BIN, args, { encoding: 'utf8' }));
}

const pointsArg = (points) => `--points=${points.map((p) => p.map(String).join(',')).join(' ')}`;

/** The page's formatting of a readout number. */
const shown = (x) => String(+x.toPrecision(8));

const openEditor = (fragment = '', options = {}) => open(chrome.browser, server.url + fragment, options);

/**
 * Drag control point `index` along `STEPS` moves (an outward spiral of `radius` pixels ending
 * `end` pixels away), waiting after each for its answer to be drawn; returns the page's
 * latencies of the steps: {event: from the input event, work: from the page's handler}.
 */
async function drag(page, index, { radius = 40, end = [30, -20], view } = {}) {
  const [x0, y0] = await page.evaluate(([i, v]) => window.lacEditor.screenOf(i, v), [index, view]);
  const before = await page.evaluate(() => window.lacEditor.probe.latencies.length);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  for (let i = 1; i <= STEPS; i++) {
    const t = i / STEPS;
    const angle = 2 * Math.PI * 1.5 * t;
    const x = x0 + end[0] * t + radius * Math.sin(angle) * Math.sin(Math.PI * t);
    const y = y0 + end[1] * t + radius * (1 - Math.cos(angle)) * Math.sin(Math.PI * t) * 0.5;
    const updates = await page.evaluate(() => window.lacEditor.probe.updates);
    await page.mouse.move(x, y);
    await settled(page, updates);
  }
  await page.mouse.up();
  await page.waitForFunction(() => window.lacEditor.idle());
  return page.evaluate((n) => ({
    event: window.lacEditor.probe.latencies.slice(n),
    work: window.lacEditor.probe.work.slice(n),
  }), before);
}

async function readout(page) {
  return page.evaluate(() => Object.fromEntries(
    [...document.querySelectorAll('#readout dd')].map((dd) => [dd.dataset.key, { value: dd.dataset.value, text: dd.textContent }]),
  ));
}

async function shot(page, name) {
  await page.screenshot({ path: join(ARTIFACTS, `${name}.png`) });
}

/** The plane canvas as PNG bytes, to tell whether the drawing changed. */
const canvasImage = (page, selector = '#plane') => page.locator(selector).screenshot();

test('segment: dragging P1 redraws the curve that lac segment gives, with the region shaded', async () => {
  const { page, context, errors } = await openEditor('#mode=segment&points=-1,0;-0.2,0.8;1,0&alpha=0.5');
  const first = await editorState(page);
  const image = await canvasImage(page);
  // The region is shown while dragging: check it mid-drag.
  const [x, y] = await page.evaluate(() => window.lacEditor.screenOf(1));
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 5, y + 5);
  await page.waitForFunction(() => window.lacEditor.state().region !== null);
  await shot(page, 'segment-dragging-with-region');
  await page.mouse.up();
  latency.segment = await drag(page, 1);
  assert.ok(latency.segment.work.length >= 200, `only ${latency.segment.work.length} updates`);
  const after = await editorState(page);
  assert.notDeepEqual(after.design.points[1], first.design.points[1]);
  assert.equal(after.error, null, JSON.stringify(after.error));
  const cli = lac('segment', pointsArg(after.design.points), '--alpha', String(after.design.alpha), '--samples', String(SAMPLES));
  assert.equal(after.answer.arc_length, cli.arc_length);
  assert.equal(after.answer.curvature_start, cli.curvature_start);
  assert.equal(after.answer.curvature_end, cli.curvature_end);
  assert.deepEqual(after.answer.samples, cli.samples);
  const shownNumbers = await readout(page);
  assert.equal(shownNumbers.arc_length.value, String(cli.arc_length));
  assert.equal(shownNumbers.arc_length.text, shown(cli.arc_length));
  assert.equal(shownNumbers.curvature_start.text, shown(cli.curvature_start));
  assert.notEqual(Buffer.compare(image, await canvasImage(page)), 0, 'the drawing did not change');
  assert.equal(after.region, null, 'the region is shaded only while dragging');

  // Hovering the curve shows s, κ and ρ of the sample under the pointer (the view is a
  // similarity: placed from the end points' screen positions).
  const sample = after.answer.samples[100];
  const p1 = await page.evaluate(() => window.lacEditor.screenOf(0));
  const p2 = await page.evaluate(() => window.lacEditor.screenOf(2));
  const d = after.design.points;
  const scale = (p2[0] - p1[0]) / (d[2][0] - d[0][0]);
  await page.mouse.move(p1[0] + (sample.x - d[0][0]) * scale, p1[1] - (sample.y - d[0][1]) * scale);
  const hover = await page.locator('#hover').textContent();
  assert.match(hover, /s = .*\nκ = .*\nρ = /);
  assert.ok(hover.includes(`s = ${shown(sample.s)}`) && hover.includes(`κ = ${shown(sample.kappa)}`), hover);
  await shot(page, 'segment-hover');
  assert.deepEqual(errors, []);
  await context.close();
});

test('compound by r_θ: dragging P1 gives what lac compound gives', async () => {
  const { page, context, errors } = await openEditor('#mode=compound');
  latency.compound = await drag(page, 1, { radius: 25, end: [10, -12] });
  const s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  const d = s.design;
  const cli = lac('compound', pointsArg(d.points), '--alpha0', String(d.alpha0), '--alpha1', String(d.alpha1), '--ratio', String(d.ratio), '--samples', String(SAMPLES));
  for (const key of ['arc_length', 'joint_s', 'curvature_joint', 'lambda']) assert.equal(s.answer[key], cli[key], key);
  assert.deepEqual(s.answer.joint, cli.joint);
  const shownNumbers = await readout(page);
  assert.equal(shownNumbers.joint_s.text, shown(cli.joint_s));
  await shot(page, 'compound');
  assert.deepEqual(errors, []);
  await context.close();
});

test('compound by four points: dragging P2 shows its region and gives what lac compound gives', async () => {
  const { page, context, errors } = await openEditor('#mode=compound4');
  const [x, y] = await page.evaluate(() => window.lacEditor.screenOf(2));
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x - 4, y + 4);
  await page.waitForFunction(() => {
    const r = window.lacEditor.state().region;
    return r && r.key.startsWith('["point",2');
  });
  await shot(page, 'compound4-dragging-with-region');
  await page.mouse.up();
  latency.compound4 = await drag(page, 2, { radius: 30, end: [-25, 15] });
  const s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  const d = s.design;
  const cli = lac('compound', pointsArg(d.points), '--alpha0', String(d.alpha0), '--alpha1', String(d.alpha1), '--samples', String(SAMPLES));
  assert.equal(s.answer.arc_length, cli.arc_length);
  assert.deepEqual(s.answer.samples, cli.samples);
  assert.deepEqual(errors, []);
  await context.close();
});

test('quasi-aesthetic: the pieces and their verdicts are those of lac quasi', async () => {
  const { page, context, errors } = await openEditor('#mode=quasi');
  latency.quasi = await drag(page, 1, { radius: 30, end: [-20, -25] });
  const s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  const d = s.design;
  const cli = lac('quasi', pointsArg(d.points), '--alpha', String(d.alpha), '--tolerance', String(d.tolerance));
  assert.deepEqual(s.answer.pieces, cli.pieces);
  assert.equal(s.answer.max, cli.max);
  const rows = await page.locator('#pieces tbody tr').count();
  assert.equal(rows, cli.pieces.length);
  const verdict = await page.locator('#pieces tbody tr td').nth(1).textContent();
  assert.equal(verdict, `${cli.pieces[0].monotone.replace('_', ' ')}${cli.pieces[0].proven ? ' (proven)' : ' (not proven)'}`);
  // A finer tolerance typed in the number field: more pieces, still proven.
  const updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.fill('#param-tolerance', '1e-9');
  await settled(page, updates);
  const fine = await editorState(page);
  assert.equal(fine.design.tolerance, 1e-9);
  assert.ok(fine.answer.pieces.length > cli.pieces.length);
  await shot(page, 'quasi');
  assert.deepEqual(errors, []);
  await context.close();
});

test('space curve: dragging P2 in the top view gives what lac space gives; the 3-D view orbits', async () => {
  const { page, context, errors } = await openEditor('#mode=space');
  await shot(page, 'space-before');
  latency.space = await drag(page, 2, { view: 'top', radius: 25, end: [-20, 10] });
  const s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  const d = s.design;
  assert.equal(d.points[2][2], 1.5, 'the top view moves x and y only');
  const cli = lac('space', pointsArg(d.points), '--alpha', String(d.alpha), '--beta', String(d.beta), '--omega', String(d.omega), '--type', String(d.type), '--samples', String(SAMPLES));
  assert.equal(s.answer.arc_length, cli.arc_length);
  assert.deepEqual(s.answer.samples.map((r) => [r.x, r.y, r.z, r.kappa, r.tau]), cli.samples.map((r) => [r.x, r.y, r.z, r.kappa, r.tau]));
  const view3d = await canvasImage(page, '#view-3d');
  const box = await page.locator('#view-3d').boundingBox();
  const updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 30, { steps: 8 });
  await page.mouse.up();
  assert.notEqual(Buffer.compare(view3d, await canvasImage(page, '#view-3d')), 0, 'the perspective view did not orbit');
  assert.equal(await page.evaluate(() => window.lacEditor.probe.updates), updates, 'orbiting asks the server nothing');
  await shot(page, 'space');
  assert.deepEqual(errors, []);
  await context.close();
});

test('undrawable: the library says what to move, the last curve stays faint; undo and redo', async () => {
  const { page, context, errors } = await openEditor('#mode=segment&points=-1,0;0,0.5;1,0&alpha=-1');
  const good = await editorState(page);
  assert.equal(good.error, null);
  // Drag P1 to (0.9, 0.9): a clothoid cannot go there.
  const [x0, y0] = await page.evaluate(() => window.lacEditor.screenOf(0));
  const [x2] = await page.evaluate(() => window.lacEditor.screenOf(2));
  const scale = (x2 - x0) / 2;
  const [x1, y1] = await page.evaluate(() => window.lacEditor.screenOf(1));
  await page.mouse.move(x1, y1);
  await page.mouse.down();
  await page.mouse.move(x0 + 1.9 * scale, y0 - 0.9 * scale, { steps: 12 });
  await page.waitForFunction(() => window.lacEditor.idle() && window.lacEditor.state().stale);
  await shot(page, 'undrawable-while-dragging');
  await page.mouse.up();
  await page.waitForFunction(() => window.lacEditor.idle());
  const bad = await editorState(page);
  assert.equal(bad.error.kind, 'not_drawable');
  assert.ok(bad.stale);
  assert.ok(bad.answer, 'the last good curve is kept');
  const message = page.locator('#message');
  assert.ok(await message.isVisible());
  const text = await message.textContent();
  assert.match(text, /Not drawable/);
  assert.match(text, /move the middle control point/);
  assert.match(text, /alpha between 0 and 1/);
  assert.match(text, /last good curve is drawn faintly/);
  await shot(page, 'undrawable');

  let updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.click('#undo');
  await settled(page, updates);
  const undone = await editorState(page);
  assert.deepEqual(undone.design, good.design);
  assert.equal(undone.error, null);
  assert.ok(!(await message.isVisible()));
  assert.equal(undone.answer.arc_length, good.answer.arc_length);

  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.keyboard.press('Control+Shift+Z');
  await settled(page, updates);
  assert.deepEqual((await editorState(page)).design, bad.design);
  assert.ok(await message.isVisible());
  assert.deepEqual(errors, []);
  await context.close();
});

test('a shared link reproduces a design with typed values exactly', async () => {
  const { page, context, errors } = await openEditor('#mode=segment');
  const typed = { alpha: '0.30000000000000004', p1x: '-0.1234567890123456', p1y: '0.7000000000000001' };
  let updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.fill('#param-alpha', typed.alpha);
  await page.locator('#param-alpha').press('Tab');
  await page.fill('[data-point="1"][data-axis="0"]', typed.p1x);
  await page.locator('[data-point="1"][data-axis="0"]').press('Tab');
  await page.fill('[data-point="1"][data-axis="1"]', typed.p1y);
  await page.locator('[data-point="1"][data-axis="1"]').press('Tab');
  await settled(page, updates);
  await page.waitForFunction(() => window.lacEditor.idle());
  const original = await editorState(page);
  assert.equal(original.design.alpha, 0.30000000000000004);
  assert.deepEqual(original.design.points[1], [-0.1234567890123456, 0.7000000000000001]);
  await page.click('#share');
  const link = page.url();
  assert.ok(link.includes('alpha=0.30000000000000004'), link);

  const other = await openEditor(link.slice(link.indexOf('#')));
  const copy = await editorState(other.page);
  assert.deepEqual(copy.design, original.design);
  assert.equal(copy.answer.arc_length, original.answer.arc_length);
  const cli = lac('segment', pointsArg(copy.design.points), '--alpha', typed.alpha);
  assert.equal(copy.answer.arc_length, cli.arc_length);
  await other.context.close();

  // Export the design as JSON, import it into a fresh page: the same design.
  const download = page.waitForEvent('download');
  await page.click('#export-json');
  const file = await (await download).path();
  const saved = JSON.parse(readFileSync(file, 'utf8'));
  assert.equal(saved.mode, 'segment');
  assert.equal(saved.alpha, 0.30000000000000004);
  assert.equal(saved.report.arc_length, original.answer.arc_length);
  const svgDownload = page.waitForEvent('download');
  await page.click('#export-svg');
  const svg = readFileSync(await (await svgDownload).path(), 'utf8');
  assert.match(svg, /^<svg xmlns="http:\/\/www.w3.org\/2000\/svg"/);
  assert.match(svg, /<path d="M-1 0 L/);

  const fresh = await openEditor('#mode=compound');
  updates = await fresh.page.evaluate(() => window.lacEditor.probe.updates);
  await fresh.page.setInputFiles('#import', file);
  await settled(fresh.page, updates);
  const imported = await editorState(fresh.page);
  assert.equal(imported.mode, 'segment');
  assert.deepEqual(imported.design, original.design);
  await fresh.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});

test('CAD export: the menu downloads the STEP, DXF, IGES and NURBS JSON that lac export writes', async () => {
  /** Choose `format` in the CAD menu; the downloaded file's name and text. */
  async function cad(page, format) {
    const download = page.waitForEvent('download');
    await page.selectOption('#export-cad', format);
    const d = await download;
    return { name: d.suggestedFilename(), text: readFileSync(await d.path(), 'utf8') };
  }
  const { page, context, errors } = await openEditor('#mode=segment');
  const step = await cad(page, 'step');
  assert.equal(step.name, 'lac-segment.step');
  assert.ok(step.text.startsWith('ISO-10303-21;'), step.text.slice(0, 40));
  assert.match(step.text, /RATIONAL_B_SPLINE_CURVE/);
  assert.ok(step.text.trimEnd().endsWith('END-ISO-10303-21;'));
  assert.equal(await page.inputValue('#export-cad'), '', 'the menu goes back to its title');
  // DXF carries no timestamp: the page's file is lac export's, byte for byte.
  const dxf = await cad(page, 'dxf');
  assert.equal(dxf.name, 'lac-segment.dxf');
  const d = (await editorState(page)).design;
  const cli = execFileSync(LAC_BIN, ['export', pointsArg(d.points), '--alpha', String(d.alpha), '--format', 'dxf', '--tolerance', '1e-6', '-o', '-'], { encoding: 'utf8' });
  assert.equal(dxf.text, cli);
  await context.close();

  // A space curve as IGES: 80-column records, the Start section first.
  const space = await openEditor('#mode=space');
  const iges = await cad(space.page, 'iges');
  assert.equal(iges.name, 'lac-space.igs');
  const lines = iges.text.split('\n').filter((l) => l.length > 0);
  assert.ok(lines.every((l) => l.replace(/\r$/, '').length === 80));
  assert.equal(lines[0][72], 'S');
  await space.context.close();

  // Quasi mode exports its exact segment (not the Bézier pieces): NURBS JSON within 1e-6.
  const quasi = await openEditor('#mode=quasi');
  const json = JSON.parse((await cad(quasi.page, 'json')).text);
  assert.equal(json.kind, 'segment');
  assert.equal(json.curves[0].degree, 3);
  assert.ok(json.max_deviation <= 1e-6);
  await quasi.context.close();
  assert.deepEqual([...errors, ...space.errors, ...quasi.errors], []);
});

test('on a narrow touch screen the points drag with a finger', async () => {
  const { page, context, errors } = await openEditor('#mode=compound', {
    viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2,
  });
  await shot(page, 'narrow-touch');
  const before = await editorState(page);
  const [x, y] = await page.evaluate(() => window.lacEditor.screenOf(1));
  const cdp = await context.newCDPSession(page);
  const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points });
  const updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await touch('touchStart', [{ x, y }]);
  for (let i = 1; i <= 10; i++) await touch('touchMove', [{ x: x - 2 * i, y: y + i }]);
  await touch('touchEnd', []);
  await settled(page, updates);
  await page.waitForFunction(() => window.lacEditor.idle());
  const after = await editorState(page);
  assert.notDeepEqual(after.design.points[1], before.design.points[1]);
  assert.equal(after.error, null);
  await shot(page, 'narrow-touch-after-drag');
  await page.locator('#panel').scrollIntoViewIfNeeded();
  await page.evaluate(() => window.scrollTo(0, document.body.scrollHeight));
  await shot(page, 'narrow-touch-panel');
  assert.deepEqual(errors, []);
  await context.close();
});

test('path: the S-shaped G2 path through an inflection, points dragged, added and removed, G1 offered', async () => {
  const { page, context, errors } = await openEditor('#mode=path');
  let s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  assert.equal(s.answer.continuity, 'g2');
  assert.equal(s.answer.straight_pieces.length, 1, 'one inflection');
  await shot(page, 'path');
  // Dragging P3 re-solves the joints: what lac path gives for the same polygon.
  latency.path = await drag(page, 3, { radius: 20, end: [12, -8] });
  s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  const cliPath = (d) => lac('path', `--polygon=${d.points.map((p) => p.map(String).join(',')).join(' ')}`,
    '--alpha', String(d.alpha), ...(d.g2 ? ['--g2'] : []), ...(d.closed ? ['--closed'] : []), '--samples', String(SAMPLES));
  let cli = cliPath(s.design);
  assert.equal(s.answer.arc_length, cli.arc_length);
  assert.deepEqual(s.answer.joints, cli.joints);
  assert.deepEqual(s.answer.samples, cli.samples);
  assert.ok(s.answer.max_curvature_jump <= 1e-9);
  const shownNumbers = await readout(page);
  assert.equal(shownNumbers.arc_length.text, shown(cli.arc_length));
  assert.equal(shownNumbers.segments.text, '4');
  // Add a point (the button: after the last), then Shift+click one onto the first leg.
  let updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.click('#add-point');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.design.points.length, 7);
  assert.equal(s.answer.segments.length, 5);
  const [a, b] = await page.evaluate(() => [window.lacEditor.screenOf(0), window.lacEditor.screenOf(1)]);
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.keyboard.down('Shift');
  await page.mouse.click((a[0] + b[0]) / 2, (a[1] + b[1]) / 2 + 3);
  await page.keyboard.up('Shift');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.design.points.length, 8);
  assert.ok(s.design.points[1][0] > 0.5 && s.design.points[1][0] < 1, JSON.stringify(s.design.points[1]));
  // Alt+click removes it again; the panel's × removes the last point.
  const p1 = await page.evaluate(() => window.lacEditor.screenOf(1));
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.keyboard.down('Alt');
  await page.mouse.click(p1[0], p1[1]);
  await page.keyboard.up('Alt');
  await settled(page, updates);
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.click('button[aria-label="remove P6"]');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.design.points.length, 6);
  cli = cliPath(s.design);
  assert.deepEqual(s.answer.samples, cli.samples);
  // α ≥ 0 cannot pass through zero curvature: the library names the leg and the page offers
  // the G1 path, which it then draws.
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.fill('#param-alpha', '0.5');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.error.kind, 'no_g2_path');
  assert.match(await page.locator('#message-text').textContent(), /leg P2-P3/);
  await shot(page, 'path-no-g2');
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.click('#message-fix');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.error, null);
  assert.equal(s.answer.continuity, 'g1');
  assert.equal(s.design.g2, false);
  // The link keeps the polygon; a closed polygon gives a closed path.
  assert.match(page.url(), /mode=path&points=.*&g2=0&closed=0/);
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.click('#param-closed');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.answer.closed, true);
  assert.equal(s.answer.segments.length, 6);
  // And the CAD menu writes the path (G1: curvature jumps at its joints, as drawn).
  const download = page.waitForEvent('download');
  await page.selectOption('#export-cad', 'json');
  const json = JSON.parse(readFileSync(await (await download).path(), 'utf8'));
  assert.equal(json.kind, 'path');
  assert.equal(json.continuity, 'G1');
  assert.ok(json.max_deviation <= 1e-6);
  await shot(page, 'path-closed-g1');
  assert.deepEqual(errors, []);
  await context.close();
});

test('spline: point types by key, drawn with their markers; what lac spline gives for the same types', async () => {
  const { page, context, errors } = await openEditor('#mode=spline');
  let s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  // The U: straight sides met with zero curvature, the bottom horizontal.
  const types = (d) => d.types.join(' ');
  const splineArgs = (d) => [`--through=${d.points.map((p) => p.map(String).join(',')).join(' ')}`,
    '--alpha', String(d.alpha), '--types', types(d),
    ...(d.types.some((t) => t === 't') ? ['--angles', d.types.map((t, i) => (t === 't' ? `${i}:${d.angles[i][0]}` : null)).filter(Boolean).join(',')] : []),
    ...(d.lines.length ? ['--lines', d.lines.map((i) => `${i}-${i + 1}`).join(',')] : [])];
  const cliSpline = (d) => lac('spline', ...splineArgs(d), '--samples', String(SAMPLES));
  let cli = cliSpline(s.design);
  assert.deepEqual(s.answer.at_points, cli.at_points);
  assert.deepEqual(s.answer.samples, cli.samples);
  assert.equal(s.answer.knots.length, 2);
  // The CAD menu writes this spline, not a path through its points: the DXF that lac export
  // --through writes for the same types, directions and straight spans, byte for byte.
  const download = page.waitForEvent('download');
  await page.selectOption('#export-cad', 'dxf');
  const dxf = await download;
  assert.equal(dxf.suggestedFilename(), 'lac-spline.dxf');
  assert.equal(readFileSync(await dxf.path(), 'utf8'), execFileSync(LAC_BIN,
    ['export', ...splineArgs(s.design), '--format', 'dxf', '--tolerance', '1e-6', '-o', '-'], { encoding: 'utf8' }));
  await shot(page, 'spline');
  // Drag P2 (the tangent point), then make it a corner with the C key: the tangent breaks.
  latency.spline = await drag(page, 2, { radius: 12, end: [6, 10] });
  s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  cli = cliSpline(s.design);
  assert.deepEqual(s.answer.at_points, cli.at_points);
  let updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.keyboard.press('c');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.design.types[2], 'c');
  assert.equal(s.answer.at_points[2].type, 'corner');
  // S makes P2 smooth again.
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.keyboard.press('s');
  await settled(page, updates);
  s = await editorState(page);
  assert.equal(s.answer.at_points[2].type, 'smooth');
  // alpha >= 0 with straight spans: refused, the point named.
  updates = await page.evaluate(() => window.lacEditor.probe.updates);
  await page.fill('#param-alpha', '0.5');
  await settled(page, updates);
  s = await editorState(page);
  assert.ok(s.error && /P1/.test(s.error.message), JSON.stringify(s.error));
  assert.deepEqual(errors, []);
  await context.close();
});

test('spline: the point menu sets a corner and a straight span; the copied link gives a fresh page the same types', async () => {
  // A link written before point types (points, no types): every point smooth.
  const through = [[0, 0], [1, 2], [3, 2.5], [5, 2.5], [6, 1.5], [7, 2.5], [8, 4.5]];
  const { page, context, errors } = await openEditor(
    `#mode=spline&points=${through.map((p) => p.join(',')).join(';')}&alpha=-1&closed=0`,
    { permissions: ['clipboard-read', 'clipboard-write'] });
  let s = await editorState(page);
  assert.equal(s.error, null, JSON.stringify(s.error));
  assert.deepEqual(s.design.types, through.map(() => 's'));
  assert.deepEqual(s.design.lines, []);
  assert.ok(s.answer.at_points.every((p) => p.type === 'smooth'));

  const menu = page.locator('#point-menu');
  /** Right-click control point `i`: its menu opens, the point's type checked and focused. */
  async function openMenu(i) {
    const [x, y] = await page.evaluate((k) => window.lacEditor.screenOf(k), i);
    await page.mouse.click(x, y, { button: 'right' });
    await menu.waitFor({ state: 'visible' });
    assert.equal(await menu.getAttribute('role'), 'menu');
    assert.equal(await menu.locator('.menu-title').textContent(), `P${i}`);
  }
  /** Do `act`, then wait for the answer it asks for. */
  async function answered(act) {
    const updates = await page.evaluate(() => window.lacEditor.probe.updates);
    await act();
    await settled(page, updates);
    return editorState(page);
  }

  // P4 a corner, by mouse. The menu's focus starts on the point's type (smooth).
  await openMenu(4);
  const focused = () => page.evaluate(() => document.activeElement.textContent);
  assert.match(await focused(), /^●?SmoothS$/);
  assert.equal(await menu.getByRole('menuitemradio', { name: /Smooth/ }).getAttribute('aria-checked'), 'true');
  assert.equal(await menu.getByRole('menuitemcheckbox', { name: /Straight span to P5/ }).getAttribute('aria-checked'), 'false');
  await page.screenshot({ path: join(ARTIFACTS, 'spline-point-menu.png') });
  s = await answered(() => menu.getByRole('menuitemradio', { name: /Corner/ }).click());
  assert.equal(await menu.count(), 0, 'a choice closes the menu');
  assert.equal(s.design.types[4], 'c');
  assert.equal(s.answer.at_points[4].type, 'corner');
  const [inAngle, outAngle] = s.answer.at_points[4].angles;
  assert.ok(Math.abs(outAngle - inAngle) > 1, 'the tangent breaks at the corner');

  // P2 to P3 straight, by keyboard: End reaches the span's checkbox, Enter chooses it.
  await openMenu(2);
  await page.keyboard.press('End');
  assert.match(await focused(), /Straight span to P3/);
  s = await answered(() => page.keyboard.press('Enter'));
  assert.deepEqual(s.design.lines, [2]);
  assert.deepEqual(s.answer.at_points[2].straight, [false, true]);
  assert.deepEqual(s.answer.at_points[3].straight, [true, false]);
  // P1 a tangent point, by its letter in the menu: the direction the curve has there.
  await openMenu(1);
  s = await answered(() => page.keyboard.press('t'));
  assert.equal(s.design.types[1], 't');
  assert.equal(typeof s.design.angles[1][0], 'number');
  assert.equal(await menu.count(), 0);

  // Escape closes the menu, and so does a click elsewhere; neither changes the design.
  const before = JSON.stringify((await editorState(page)).design);
  await openMenu(5);
  await page.keyboard.press('Escape');
  assert.equal(await menu.count(), 0, 'Escape closes the menu');
  await openMenu(5);
  await page.mouse.click(20, 400);
  assert.equal(await menu.count(), 0, 'a click elsewhere closes the menu');
  // Shift+F10 opens the selected point's menu (P5, right-clicked last) from the keyboard.
  await page.keyboard.press('Shift+F10');
  await menu.waitFor({ state: 'visible' });
  assert.equal(await menu.locator('.menu-title').textContent(), 'P5');
  await page.keyboard.press('Escape');
  assert.equal(await menu.count(), 0);
  // The last point of an open spline has no span after it.
  await openMenu(6);
  assert.equal(await menu.getByRole('menuitemcheckbox').isDisabled(), true);
  await page.keyboard.press('Escape');
  assert.equal(JSON.stringify((await editorState(page)).design), before);

  // Copy the link; a fresh page finds the same types, directions and straight spans, and the
  // spline lac spline draws with them.
  const original = await editorState(page);
  await page.click('#share');
  await page.locator('#toast', { hasText: 'Link copied' }).waitFor();
  const link = await page.evaluate(() => navigator.clipboard.readText());
  assert.equal(link, page.url());
  assert.match(link, /&types=stsscss&/);
  assert.match(link, new RegExp(`&angles=1:${original.design.angles[1][0]}&`));
  assert.match(link, /&lines=2&/);
  const other = await openEditor(link.slice(link.indexOf('#')));
  const copy = await editorState(other.page);
  assert.equal(copy.error, null, JSON.stringify(copy.error));
  assert.deepEqual(copy.design, original.design);
  assert.deepEqual(copy.answer.at_points, original.answer.at_points);
  const d = copy.design;
  const cli = lac('spline', `--through=${d.points.map((p) => p.join(',')).join(' ')}`, '--alpha', String(d.alpha),
    '--types', d.types.join(' '), '--angles', `1:${d.angles[1][0]}`, '--lines', '2-3', '--samples', String(SAMPLES));
  assert.deepEqual(copy.answer.at_points, cli.at_points);
  assert.deepEqual(copy.answer.samples, cli.samples);
  // Its CAD file is the spline with the corner: G0 there, within the tolerance.
  const download = other.page.waitForEvent('download');
  await other.page.selectOption('#export-cad', 'json');
  const json = JSON.parse(readFileSync(await (await download).path(), 'utf8'));
  assert.equal(json.kind, 'spline');
  assert.equal(json.continuity, 'G0');
  assert.ok(json.max_deviation <= 1e-6);
  assert.deepEqual(other.errors, []);
  await other.context.close();
  assert.deepEqual(errors, []);
  await context.close();
});
