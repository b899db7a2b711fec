// Shared by the browser tests: start the real `lac serve` binary on a free port, and Debian's
// Chromium headless through playwright-core (never a downloaded browser).

import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve, dirname } from 'node:path';
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
