// What the browser tests share: the penumbra server they start, headless Chromium, a static file
// server for pages of their own, and pixel statistics of the element's canvas.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { launchFirefox } from './firefox_adapter.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
export const repoRoot = path.resolve(here, '..', '..');
export const webDir = path.join(repoRoot, 'web');

export const binaryPath = process.env.PENUMBRA_BINARY
  ? path.resolve(process.env.PENUMBRA_BINARY)
  : path.join(repoRoot, 'build', 'penumbra');
// The server tests run in Chromium (playwright-core) or, with PENUMBRA_TEST_BROWSER=firefox, in
// Firefox (puppeteer-core, firefox_adapter.mjs); the scripted-server tests need Playwright.
export const browserName = process.env.PENUMBRA_TEST_BROWSER || 'chromium';
const browsers = {
  chromium: { path: process.env.CHROMIUM || '/usr/bin/chromium', driver: 'playwright-core', apt: 'chromium', variable: 'CHROMIUM' },
  firefox: { path: process.env.FIREFOX || '/usr/bin/firefox-esr', driver: 'puppeteer-core', apt: 'firefox-esr', variable: 'FIREFOX' },
};
const chosen = browsers[browserName];

const SERVER_START_TIMEOUT_MS = 60_000; // lavapipe compiles every pipeline before the first frame
const SERVER_STOP_GRACE_MS = 3_000;
const LOG_TAIL_LINES = 40;

// Why the tests cannot run here, or null. In CI a missing piece is a failure, elsewhere a skip.
export async function missingPrerequisite({ needsServer = true } = {}) {
  if (needsServer && !fs.existsSync(binaryPath)) return `no penumbra binary at ${binaryPath} (set PENUMBRA_BINARY)`;
  if (!chosen) return `PENUMBRA_TEST_BROWSER=${browserName} is neither chromium nor firefox`;
  if (!fs.existsSync(chosen.path)) {
    return `no ${browserName} at ${chosen.path} (apt install ${chosen.apt}, or set ${chosen.variable})`;
  }
  try {
    await import(chosen.driver);
  } catch {
    return `${chosen.driver} is not installed: run npm ci --prefix ${path.relative(repoRoot, here)} in ${repoRoot}`;
  }
  return null;
}

export async function launchBrowser() {
  if (browserName === 'firefox') return launchFirefox(chosen.path);
  const { chromium } = await import('playwright-core');
  return chromium.launch({ executablePath: chosen.path, args: ['--no-sandbox'], timeout: 30_000 });
}

// Starts `penumbra serve` on an ephemeral loopback port; resolves once it prints the address.
// The server renders on lavapipe unless PENUMBRA_TEST_DEVICE names another device, as the GPU
// tests do.
export function startServer(extraArgs = []) {
  const args = ['serve', 'cornell', '--port', '0', '--width', '96', '--height', '64', '--spp', '1', ...extraArgs];
  const env = { ...process.env, PENUMBRA_DEVICE: process.env.PENUMBRA_TEST_DEVICE || 'llvmpipe' };
  const child = spawn(binaryPath, args, { env, stdio: ['ignore', 'pipe', 'pipe'] });
  const log = [];
  const remember = (stream) => (chunk) => {
    for (const line of chunk.toString().split('\n')) {
      if (line) log.push(`${stream}: ${line}`);
    }
    if (log.length > 400) log.splice(0, log.length - 400);
  };
  child.stdout.on('data', remember('stdout'));
  child.stderr.on('data', remember('stderr'));
  // A test process that dies for any reason must not leave a renderer spinning.
  const killOnExit = () => child.kill('SIGKILL');
  process.on('exit', killOnExit);

  const server = {
    child,
    logTail: () => log.slice(-LOG_TAIL_LINES).join('\n'),
    stop: () => stopChild(child).finally(() => process.off('exit', killOnExit)),
  };
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => fail(`did not print its address within ${SERVER_START_TIMEOUT_MS / 1000} s`),
      SERVER_START_TIMEOUT_MS);
    const fail = (why) => {
      clearTimeout(timer);
      server.stop();
      reject(new Error(`penumbra ${args.join(' ')} ${why}\n${server.logTail()}`));
    };
    let pending = '';
    const lookForAddress = (chunk) => {
      pending += chunk.toString();
      const match = /penumbra: serving (http:\/\/127\.0\.0\.1:(\d+)\/)/.exec(pending);
      if (!match) return;
      clearTimeout(timer);
      child.stdout.off('data', lookForAddress);
      server.httpUrl = match[1];
      server.port = Number(match[2]);
      server.wsUrl = `ws://127.0.0.1:${server.port}/ws`;
      resolve(server);
    };
    child.stdout.on('data', lookForAddress);
    child.on('error', (error) => fail(`could not start: ${error.message}`));
    child.on('exit', (code, signal) => {
      if (!server.port) fail(`exited (${signal || code}) before printing its address`);
    });
  });
}

// SIGTERM, then SIGKILL if it has not gone after a grace period.
function stopChild(child) {
  if (child.exitCode !== null || child.signalCode !== null) return Promise.resolve();
  return new Promise((resolve) => {
    const killer = setTimeout(() => child.kill('SIGKILL'), SERVER_STOP_GRACE_MS);
    child.once('exit', () => {
      clearTimeout(killer);
      resolve();
    });
    child.kill('SIGTERM');
  });
}

// Serves files of web/ from another origin than the penumbra server; `rewrite(name, text)` may
// change a page on its way out (the embed example's server address).
export function startStaticServer(rewrite = (name, text) => text) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css' };
  const server = http.createServer((request, response) => {
    const name = new URL(request.url, 'http://localhost').pathname.slice(1);
    const type = types[path.extname(name)];
    const file = path.join(webDir, name);
    if (!/^[\w.-]+$/.test(name) || !type || !fs.existsSync(file)) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { 'content-type': `${type}; charset=utf-8`, 'cache-control': 'no-store' });
    response.end(rewrite(name, fs.readFileSync(file, 'utf8')));
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => resolve({
      url: `http://127.0.0.1:${server.address().port}/`,
      close: () => new Promise((done) => {
        server.closeAllConnections();
        server.close(() => done());
      }),
    }));
  });
}

// ---- the element in a page ----

// Resolves once the element (the first on the page unless a selector is given) has drawn more
// than `count` frames.
export async function waitForFramesDrawn(page, count, timeoutMs, selector = 'penumbra-view') {
  await page.waitForFunction(([sel, n]) => document.querySelector(sel)?.framesDrawn > n,
    [selector, count], { timeout: timeoutMs, polling: 50 });
  return framesDrawn(page, selector);
}

export function framesDrawn(page, selector = 'penumbra-view') {
  return page.evaluate((sel) => document.querySelector(sel).framesDrawn, selector);
}

// Waits for `frames` more frames, then reads the canvas: {width, height, rgb: [r,g,b,...]}.
export async function nextPicture(page, timeoutMs, frames = 1) {
  const now = await framesDrawn(page);
  await waitForFramesDrawn(page, now + frames - 1, timeoutMs);
  return readCanvas(page);
}

export function readCanvas(page, selector = 'penumbra-view') {
  return page.evaluate((sel) => {
    const canvas = document.querySelector(sel).shadowRoot.querySelector('canvas');
    const rgba = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    const rgb = [];
    for (let i = 0; i < rgba.length; i += 4) rgb.push(rgba[i], rgba[i + 1], rgba[i + 2]);
    return { width: canvas.width, height: canvas.height, rgb };
  }, selector);
}

// Mean red, green and blue (0..255) over the columns [x0, x1) of the picture.
export function meanColour(picture, x0, x1) {
  const sum = [0, 0, 0];
  let count = 0;
  for (let y = 0; y < picture.height; y++) {
    for (let x = x0; x < x1; x++) {
      const i = (y * picture.width + x) * 3;
      for (let c = 0; c < 3; c++) sum[c] += picture.rgb[i + c];
      count++;
    }
  }
  return sum.map((s) => s / count);
}

// The picture averaged over blocks of block x block pixels: per-pixel noise (a path tracer's at
// one sample per pixel is large) averages out, while a moved wall or another colour does not.
export function blockMeans(picture, block = 8) {
  const columns = Math.floor(picture.width / block);
  const rows = Math.floor(picture.height / block);
  const means = [];
  for (let by = 0; by < rows; by++) {
    for (let bx = 0; bx < columns; bx++) {
      const sum = [0, 0, 0];
      for (let y = by * block; y < (by + 1) * block; y++) {
        for (let x = bx * block; x < (bx + 1) * block; x++) {
          const i = (y * picture.width + x) * 3;
          for (let c = 0; c < 3; c++) sum[c] += picture.rgb[i + c];
        }
      }
      means.push(...sum.map((s) => s / (block * block)));
    }
  }
  return means;
}

// Mean absolute difference (0..255) of two pictures' block means.
export function pictureDifference(a, b) {
  if (a.width !== b.width || a.height !== b.height) return 255;
  const ma = blockMeans(a);
  const mb = blockMeans(b);
  let sum = 0;
  for (let i = 0; i < ma.length; i++) sum += Math.abs(ma[i] - mb[i]);
  return sum / ma.length;
}

// Resolves once the element's latest stats (or, with 'hello', its hello) satisfy `accept`, a
// function run in the page on that object.
export async function waitForServerState(page, accept, timeoutMs, which = 'stats') {
  const handle = await page.waitForFunction(([property, acceptSource]) => {
    const state = document.querySelector('penumbra-view')[property];
    // eslint-disable-next-line no-new-func -- the test's own predicate, passed as source
    return state && new Function(`return (${acceptSource})`)()(state) ? state : null;
  }, [which, accept.toString()], { timeout: timeoutMs, polling: 50 });
  return handle.jsonValue();
}

// With PENUMBRA_BROWSER_ARTIFACTS set, screenshots of the page go into that folder.
export function savePicture(page, name) {
  const dir = process.env.PENUMBRA_BROWSER_ARTIFACTS;
  if (!dir) return Promise.resolve();
  fs.mkdirSync(dir, { recursive: true });
  return page.screenshot({ path: path.join(dir, `${name}.png`) });
}
