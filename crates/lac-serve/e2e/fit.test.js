// The Fit mode in a real browser: points pasted and imported (an SVG path gives its nodes and
// points along it), the fit drawn with its points coloured by their distance, the points' box
// following drags and undo, the fit's options (G1, the most segments, α's range, one α, a fixed
// α) followed as they change (the fit the page draws is lac fit's, bit for bit), the tolerance slider dragged over 1,000 points with the frames
// the page keeps and the time to the last fit printed, and the fit exported for CAD.
// Screenshots go to $LAC_ARTIFACTS.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { startServer, startBrowser, openEditor, editorState, settled, LAC_BIN, ARTIFACTS } from './harness.js';

let server;
let chrome;
const figures = [];

before(async () => {
  server = await startServer();
  chrome = await startBrowser();
});

after(async () => {
  if (figures.length) {
    const report = ['the tolerance slider dragged over 1,000 points, measured in the page:', ...figures].join('\n');
    console.log(report);
    writeFileSync(join(ARTIFACTS, 'fit-drag.txt'), report + '\n');
  }
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

/** `n` points of one period of a sine: a path of several segments (an S at each crossing). */
function sinePoints(n = 1000) {
  return Array.from({ length: n }, (_, k) => {
    const x = (2 * Math.PI * k) / (n - 1);
    return [+x.toFixed(6), +Math.sin(x).toFixed(6)];
  });
}

/** `n` points of a logarithmic spiral with a little noise: one segment (α = 1). */
function spiralPoints(n = 1000) {
  return Array.from({ length: n }, (_, k) => {
    const t = (1.4 * Math.PI * k) / (n - 1);
    const r = Math.exp(0.2 * t) * (1 + 0.0015 * Math.sin(7.3 * k));
    return [+(r * Math.cos(t)).toFixed(6), +(r * Math.sin(t)).toFixed(6)];
  });
}

const text = (points) => points.map(([x, y]) => `${x} ${y}`).join('\n');

const openFit = () => openEditor(chrome.browser, `${server.url}#mode=fit`);

const updates = (page) => page.evaluate(() => window.lacEditor.probe.updates);

/** Do `action` and wait for the answer to what it changed. */
async function andSettle(page, action) {
  const n = await updates(page);
  await action();
  // A path of a thousand points may take seconds on a busy machine.
  await settled(page, n, 60000);
  return editorState(page);
}

/** Paste `points` into the box and fit them. */
const paste = (page, points) => andSettle(page, async () => {
  await page.fill('#fit-points', text(points));
  await page.click('#fit-apply');
});

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

/** Type `value` into parameter `key`'s field, as a user does. */
const typeParam = (page, key, value) => andSettle(page, () => page.fill(`#param-${key}`, String(value)));

/** Set parameter `key`'s checkbox. */
const tick = (page, key, on) => andSettle(page, () => page.setChecked(`#param-${key}`, on));

test('fit: pasted points of an arc are fitted within the tolerance, coloured, followed by the slider, exported', async () => {
  const { page, context, errors } = await openFit();
  const points = arcPoints();
  let state = await paste(page, points);
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.deepEqual(state.design.points, points, 'the text is read to the same doubles');
  const tolerance = state.design.tolerance;
  assert.equal(Number(await readout(page, 'point_count')), 200);
  const maxDistance = Number(await readout(page, 'max_distance'));
  assert.ok(maxDistance <= tolerance, `largest distance ${maxDistance} > tolerance ${tolerance}`);
  assert.equal(state.answer.distances.length, 200);
  assert.ok(Number(await readout(page, 'fitted_segments')) >= 1);
  // A circle: one segment, α anything (the curvature is constant), radius 2.
  assert.ok(state.answer.samples.every((r) => Math.abs(r.kappa - 0.5) < 1e-3), 'κ = 1/2 along the fit');
  assert.match(await page.textContent('#readout dd[data-key="max_distance"]'), /^\d\.\d\de-\d ≤ 0\.01$/);
  assert.equal(Number(await readout(page, 'worst_point')), state.answer.worst_point);

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
  let n = await updates(page);
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

test('fit: an imported SVG path gives its nodes and points along its length, in order, none twice', async () => {
  const { page, context, errors } = await openFit();
  // Every kind of command, relative ones, a smooth cubic and quadratic, an arc.
  const d = 'M10 80 C 40 10, 65 10, 95 80 S 150 150, 180 80 l 30 -20 h 20 v 10 Q 260 40 280 70 T 320 70 A 20 20 0 0 1 360 70';
  const nodes = [[10, 80], [95, 80], [180, 80], [210, 60], [230, 60], [230, 70], [280, 70], [320, 70], [360, 70]];
  const svg = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 400 200"><path d="${d}" fill="none" stroke="black"/></svg>`;
  const state = await andSettle(page, () => page.setInputFiles('#fit-import', {
    name: 'curve.svg', mimeType: 'image/svg+xml', buffer: Buffer.from(svg),
  }));
  const points = state.design.points;
  // y turned up.
  const at = nodes.map(([x, y]) => points.findIndex(([px, py]) => px === x && py === -y));
  assert.ok(at.every((i) => i >= 0), `every node is a point: ${JSON.stringify(at)}`);
  assert.deepEqual([...at].sort((a, b) => a - b), at, 'the nodes in their order along the path');
  assert.equal(at[0], 0);
  assert.equal(at[at.length - 1], points.length - 1);
  const gaps = points.slice(1).map((p, i) => Math.hypot(p[0] - points[i][0], p[1] - points[i][1]));
  assert.ok(Math.min(...gaps) > 1e-3, `no point repeats its neighbour (closest ${Math.min(...gaps)})`);
  assert.ok(points.length > 200 && points.length <= 209, `${points.length} points: 200 along the path and its nodes`);
  assert.equal(state.design.closed, false);
  // The tolerance slider spans the points' size (about 350 here): up to 10^2.
  assert.equal(await page.getAttribute('[data-slider="tolerance"]', 'max'), '2');
  const box = await page.inputValue('#fit-points');
  assert.equal(box.split('\n').length, points.length, 'the box shows the points');

  // An elliptical arc of an SVG (its units pixels): fitted within the tolerance.
  const ellipse = '<svg xmlns="http://www.w3.org/2000/svg"><path d="M 20 150 A 200 150 0 0 1 480 140"/></svg>';
  const arc = await andSettle(page, () => page.setInputFiles('#fit-import', {
    name: 'arc.svg', mimeType: 'image/svg+xml', buffer: Buffer.from(ellipse),
  }));
  assert.equal(arc.error, null, JSON.stringify(arc.error));
  assert.deepEqual([arc.design.points[0], arc.design.points.at(-1)], [[20, -150], [480, -140]]);
  assert.ok(arc.answer.max_distance <= arc.design.tolerance);
  await page.screenshot({ path: join(ARTIFACTS, 'fit-svg.png') });

  // A closed path: the fit is closed, and the first point is not repeated at the end.
  const square = await page.evaluate(async () => {
    const { svgPoints } = await import('/app/points.js');
    return svgPoints('<svg xmlns="http://www.w3.org/2000/svg"><path d="m0 0 10 0 0 10 -10 0z"/></svg>');
  });
  assert.equal(square.closed, true);
  assert.deepEqual(square.points[0], [0, 0]);
  assert.notDeepEqual(square.points[square.points.length - 1], [0, 0]);
  for (const corner of [[10, 0], [10, -10], [0, -10]]) assert.ok(square.points.some((p) => p[0] === corner[0] && p[1] === corner[1]), `corner ${corner}`);
  const bad = await page.evaluate(async () => (await import('/app/points.js')).svgPoints('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 L 1"/></svg>'));
  assert.match(bad.error, /not a path/);

  await context.close();
  assert.deepEqual(errors, []);
});

test('fit: the points\' box shows the points as they are after a drag, and after undo', async () => {
  const { page, context, errors } = await openFit();
  const first = await editorState(page);
  assert.equal(await page.inputValue('#fit-points'), text(first.design.points));
  const [x, y] = await page.evaluate(() => window.lacEditor.screenOf(40));
  let state = await andSettle(page, async () => {
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let k = 1; k <= 10; k++) await page.mouse.move(x + 3 * k, y + 2 * k);
    await page.mouse.up();
  });
  await page.waitForFunction(() => window.lacEditor.idle());
  state = await editorState(page);
  assert.notDeepEqual(state.design.points[40], first.design.points[40], 'the point moved');
  assert.equal(await page.inputValue('#fit-points'), text(state.design.points), 'the box after the drag');
  state = await andSettle(page, () => page.click('#undo'));
  assert.deepEqual(state.design.points, first.design.points);
  assert.equal(await page.inputValue('#fit-points'), text(first.design.points), 'the box after undo');
  await context.close();
  assert.deepEqual(errors, []);
});

test('fit: G1, the most segments, α\'s range, one α and a fixed α are followed as they change, as lac fit gives them; refusals say what to do', async () => {
  const { page, context, errors } = await openFit();
  let state = await paste(page, sinePoints(300));
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.equal(state.answer.continuity, 'g2');
  assert.ok(state.answer.fitted_segments > 1);

  state = await tick(page, 'g1', true);
  assert.equal(state.answer.continuity, 'g1');
  assert.match(await page.textContent('#readout dd[data-key="fitted_segments"]'), /\(G1\)/);
  state = await tick(page, 'g1', false);

  // One segment cannot follow a sine: the refusal says so, and offers more segments.
  state = await typeParam(page, 'max_segments', 1);
  assert.equal(state.error.kind, 'fit_tolerance_not_met');
  assert.equal(await page.textContent('#message-title'), 'Cannot fit:');
  assert.match(await page.textContent('#message-text'), /at most 1 segment /);
  assert.equal(await page.textContent('#message-fix'), 'Allow 2 segments');
  await page.screenshot({ path: join(ARTIFACTS, 'fit-refused.png') });
  // Two are not enough either; four are.
  state = await andSettle(page, () => page.click('#message-fix'));
  assert.equal(state.design.max_segments, 2);
  assert.equal(await page.inputValue('#param-max_segments'), '2');
  assert.equal(await page.textContent('#message-fix'), 'Allow 4 segments');
  state = await andSettle(page, () => page.click('#message-fix'));
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.ok(state.answer.fitted_segments <= 4);
  // Not a whole number: the field says why, the fit keeps 4.
  await page.fill('#param-max_segments', '2.5');
  assert.match(await page.textContent('#note-param-max_segments'), /a whole number ≥ 1 and ≤ 64; the curve keeps 4/);
  state = await typeParam(page, 'max_segments', 16);

  // α in a range: every piece's α within it (the range rows apply; the fixed α's does not).
  assert.equal(await page.isDisabled('#param-alpha'), true);
  state = await typeParam(page, 'alpha_min', -0.8);
  state = await typeParam(page, 'alpha_max', -0.4);
  assert.equal(state.error, null, JSON.stringify(state.error));
  const alphas = () => JSON.stringify(state.answer.pieces.map((p) => p.alpha));
  assert.ok(state.answer.pieces.every((p) => p.alpha >= -0.8 && p.alpha <= -0.4), alphas());
  state = await tick(page, 'shared', true);
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.equal(new Set(state.answer.pieces.map((p) => p.alpha)).size, 1, `one α for every segment: ${alphas()}`);
  state = await tick(page, 'shared', false);

  // A range the wrong way round is said at once, without asking the server.
  const asked = await page.evaluate(() => window.lacEditor.probe.drawn.length);
  state = await typeParam(page, 'alpha_min', 0);
  assert.equal(state.error.kind, 'invalid_input');
  assert.equal(await page.textContent('#message-title'), 'Cannot fit:');
  assert.match(await page.textContent('#message-text'), /α from \(0\) is above α to \(-0\.4\)/);
  assert.equal(await page.evaluate(() => window.lacEditor.probe.drawn.length), asked, 'no request');
  await page.screenshot({ path: join(ARTIFACTS, 'fit-range-refused.png') });
  state = await typeParam(page, 'alpha_min', -0.8);
  assert.equal(state.error, null);

  // α fixed: every piece takes it; the range's rows no longer apply.
  state = await tick(page, 'free', false);
  assert.equal(await page.isDisabled('#param-alpha_min'), true);
  assert.equal(await page.isDisabled('#param-alpha'), false);
  state = await typeParam(page, 'alpha', -0.5);
  assert.equal(state.error, null, JSON.stringify(state.error));
  assert.ok(state.answer.pieces.every((p) => p.alpha === -0.5));
  // The fit the page draws is lac fit's, to the last bit.
  const file = join(ARTIFACTS, 'fit-sine.txt');
  writeFileSync(file, text(state.design.points) + '\n');
  const cli = JSON.parse(execFileSync(LAC_BIN, ['fit', file, '--tolerance', '0.01', '--max-segments', '16', '--alpha', '-0.5', '--samples', '257'], { encoding: 'utf8' }));
  const { distances, ...report } = state.answer;
  assert.deepEqual(report, cli);

  // The link carries every option (written when a field is left).
  await page.press('#param-alpha', 'Tab');
  const link = await page.evaluate(() => window.location.hash);
  for (const part of ['max_segments=16', 'g1=0', 'free=0', 'alpha_min=-0.8', 'alpha_max=-0.4', 'shared=0', 'alpha=-0.5']) assert.ok(link.includes(part), `${part} in ${link.slice(-200)}`);
  await page.screenshot({ path: join(ARTIFACTS, 'fit-options.png') });
  await context.close();
  assert.deepEqual(errors, []);
});

/**
 * Drag the tolerance slider with the mouse from 10^`from` to 10^`to` in `steps` moves
 * `interval` ms apart, counting the page's animation frames; returns the figures: frames a
 * second during the drag, the longest frame, the fits drawn during it, the time from the last
 * move to the last fit drawn, and the server's median time per fit. `shot`: a screenshot's
 * name, taken before the mouse is let go.
 */
async function dragTolerance(page, from, to, { steps = 60, interval = 16, shot = null } = {}) {
  await typeParam(page, 'tolerance', +(10 ** from).toPrecision(3));
  const slider = page.locator('[data-slider="tolerance"]');
  const box = await slider.boundingBox();
  const { min, max } = await slider.evaluate((el) => ({ min: Number(el.min), max: Number(el.max) }));
  // The thumb's centre runs from half its width in from one end to as far from the other.
  const thumb = 8;
  const xAt = (v) => box.x + thumb + ((box.width - 2 * thumb) * (v - min)) / (max - min);
  const y = box.y + box.height / 2;
  const before = await page.evaluate(() => {
    const p = window.lacEditor.probe;
    window.fitFrames = [];
    if (!window.fitMoves) {
      document.querySelector('[data-slider="tolerance"]').addEventListener('input', (e) => window.fitMoves.push(e.timeStamp));
    }
    window.fitMoves = [];
    window.fitCounting = true;
    const count = (t) => {
      window.fitFrames.push(t);
      if (window.fitCounting) requestAnimationFrame(count);
    };
    requestAnimationFrame(count);
    return { drawn: p.drawn.length, phases: p.phases.length };
  });
  await page.mouse.move(xAt(from), y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(xAt(from + ((to - from) * k) / steps), y);
    await page.waitForTimeout(interval);
  }
  if (shot) await page.screenshot({ path: join(ARTIFACTS, shot) });
  await page.mouse.up();
  await page.waitForFunction(() => window.lacEditor.idle() && window.lacEditor.probe.drawn.length > 0
    && window.lacEditor.probe.drawn.at(-1).generation === window.lacEditor.generation(), null, { timeout: 60000 });
  return page.evaluate((start) => {
    window.fitCounting = false;
    const { fitMoves: moves, fitFrames: frames } = window;
    const p = window.lacEditor.probe;
    const [first, last] = [moves[0], moves[moves.length - 1]];
    const during = frames.filter((t) => t >= first && t <= last);
    const gaps = during.slice(1).map((t, i) => t - during[i]);
    const drawn = p.drawn.slice(start.drawn);
    const fits = p.phases.slice(start.phases).map((ph) => ph[1]).sort((a, b) => a - b);
    return {
      moves: moves.length,
      seconds: (last - first) / 1000,
      fps: (during.length - 1) / ((last - first) / 1000),
      longestFrame: Math.max(...gaps),
      fitsDuring: drawn.filter((d) => d.at <= last).length,
      lastFit: drawn[drawn.length - 1].at - last,
      generations: drawn.map((d) => d.generation),
      fitMedian: fits[Math.floor(fits.length / 2)],
      lastRequest: p.phases[p.phases.length - 1][1],
    };
  }, before);
}

test('fit: 1,000 points follow a drag of the tolerance slider, the newest fit drawn last; the frames a second are printed', async () => {
  const { page, context, errors } = await openFit();
  for (const [name, points, from, to, file] of [
    ['one segment (a spiral)', spiralPoints(), -1.5, -2.3, 'segment'],
    ['a path (a sine)', sinePoints(), -1, -2.4, 'path'],
  ]) {
    let state = await paste(page, points);
    assert.equal(state.design.points.length, 1000);
    const m = await dragTolerance(page, from, to, { shot: `fit-1000-${file}-dragging.png` });
    state = await editorState(page);
    // The fit drawn last is of the slider's last value, and the fits were drawn in order.
    const slider = Number(await page.inputValue('[data-slider="tolerance"]'));
    assert.equal(state.design.tolerance, +(10 ** slider).toPrecision(3));
    assert.equal(await page.inputValue('#param-tolerance'), String(state.design.tolerance));
    if (state.error) assert.equal(state.error.kind, 'fit_tolerance_not_met', state.error.message);
    else assert.equal(state.answer.tolerance, state.design.tolerance, 'the fit drawn is the last tolerance\'s');
    assert.ok(m.generations.every((g, i) => i === 0 || g > m.generations[i - 1]), `fits drawn in order: ${m.generations}`);
    assert.equal(m.generations.at(-1), await page.evaluate(() => window.lacEditor.generation()));
    assert.ok(m.moves > 1, 'the slider moved');
    figures.push(`${name.padEnd(24)} ${String(m.moves).padStart(3)} moves in ${m.seconds.toFixed(2)} s: `
      + `${m.fps.toFixed(1)} frames a second (longest frame ${m.longestFrame.toFixed(0)} ms), `
      + `${m.fitsDuring} fits drawn meanwhile (median ${m.fitMedian.toFixed(0)} ms a request), `
      + `last move to its fit drawn ${m.lastFit.toFixed(0)} ms (its request ${m.lastRequest.toFixed(0)} ms)`);
    await page.screenshot({ path: join(ARTIFACTS, `fit-1000-${file}.png`) });
  }
  await context.close();
  assert.deepEqual(errors, []);
});
