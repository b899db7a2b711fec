// Shared by the browser tests: start the real `lac serve` binary on a free port, and Debian's
// Chromium headless through playwright-core (never a downloaded browser); open the editor in
// it, read its state, wait for its answers.

import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve, dirname, extname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = dirname(fileURLToPath(import.meta.url));
export const ROOT = resolve(here, '../../..');

/** The `lac` binary: $LAC_BIN, or the one `cargo test` builds (test profile, optimised), as
 * `make e2e` passes it. */
export const LAC_BIN = process.env.LAC_BIN || join(ROOT, 'target/debug/lac');

/** Where screenshots go: $LAC_ARTIFACTS, or a fresh temporary directory. */
export const ARTIFACTS = process.env.LAC_ARTIFACTS || mkdtempSync(join(tmpdir(), 'lac-e2e-'));
mkdirSync(ARTIFACTS, { recursive: true });

/** Start `lac serve --port 0` and resolve with {url, stop()} once it prints its URL. */
export function startServer() {
  return new Promise((resolveStart, reject) => {
    const child = spawn(LAC_BIN, ['serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    let err = '';
    const timer = setTimeout(() => {
      child.kill();
      reject(new Error(`lac serve printed no URL within 20 s: ${out} ${err}`));
    }, 20000);
    child.stdout.on('data', (chunk) => {
      out += chunk;
      const m = out.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (m) {
        clearTimeout(timer);
        resolveStart({
          url: m[0],
          stop: () => new Promise((done) => {
            if (child.exitCode !== null) return done();
            child.once('exit', done);
            child.kill('SIGTERM');
          }),
        });
      }
    });
    child.stderr.on('data', (chunk) => { err += chunk; });
    child.on('error', (e) => {
      clearTimeout(timer);
      reject(new Error(`cannot start ${LAC_BIN}: ${e.message} (build it with cargo test --workspace --no-run, or set LAC_BIN)`));
    });
    child.on('exit', (code) => {
      clearTimeout(timer);
      if (!out.includes('http://')) reject(new Error(`lac serve exited with ${code}: ${err}`));
    });
  });
}

/** Launch headless Chromium; resolves with {browser, close()}. Playwright gives every launch
 * a fresh, empty profile (its own --user-data-dir in a temporary directory, removed at close),
 * and refuses the flag from the caller, so it is not passed here. */
export async function startBrowser() {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
    ],
  });
  return {
    browser,
    close: () => browser.close(),
  };
}

/** $LAC_WEB: a directory to serve the page from instead of the binary's copy (`lac serve`
 * embeds web/ when it is compiled): to try a change of the page without rebuilding, or to run
 * the tests against another version of it (e.g. `git worktree` of an older commit). */
export const WEB_DIR = process.env.LAC_WEB ? resolve(process.env.LAC_WEB) : null;

const MEDIA = { '.js': 'text/javascript', '.css': 'text/css', '.svg': 'image/svg+xml', '.html': 'text/html' };

/** With $LAC_WEB, answer the page's requests in `context` (`/` and `/app/…`) from it. */
export async function servePage(context) {
  if (!WEB_DIR) return;
  await context.route((url) => url.pathname === '/' || url.pathname.startsWith('/app/'), (route) => {
    const { pathname } = new URL(route.request().url());
    const file = pathname === '/' ? 'index.html' : pathname.slice('/app/'.length);
    try {
      const body = readFileSync(join(WEB_DIR, file));
      route.fulfill({ status: 200, body, contentType: MEDIA[extname(file)] || 'application/octet-stream' });
    } catch {
      route.fulfill({ status: 404, body: 'not found' });
    }
  });
}

/**
 * Open the editor at `url` in a fresh context of `browser` (1280 × 800 unless `options`, the
 * context's, say otherwise; `init`: a function the page runs before its own scripts), once it
 * has drawn its first answer: {page, context, errors}. `errors` collects the page's errors; a
 * 4xx answer (the browser's "failed to load resource" in the console) is expected, not one.
 */
export async function openEditor(browser, url, { init = null, ...options } = {}) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, ...options });
  await servePage(context);
  if (init) await context.addInitScript(init);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => {
    if (m.type() === 'error' && !/status of 4\d\d/.test(m.text())) errors.push(m.text());
  });
  await page.goto(url);
  await page.waitForFunction(() => window.lacEditor && window.lacEditor.probe.updates >= 1 && window.lacEditor.idle());
  return { page, context, errors };
}

/** The page's state (main.js: `lacEditor.state()`). */
export const editorState = (page) => page.evaluate(() => window.lacEditor.state());

/** Wait until the page has drawn an answer newer than `updates` and has nothing in flight. */
export async function settled(page, updates, timeout = 30000) {
  await page.waitForFunction((n) => window.lacEditor.probe.updates > n && window.lacEditor.idle(), updates, { timeout });
}
