// `penumbra serve` seen from headless Chromium: the page at / and <penumbra-view> against the
// real server rendering the Cornell box at 96x64, one sample per pixel (on lavapipe in CI).
import assert from 'node:assert/strict';
import { after, before, describe, test } from 'node:test';

import {
  launchBrowser, meanColour, missingPrerequisite, nextPicture, pictureDifference, readCanvas,
  savePicture, startServer, startStaticServer, waitForFramesDrawn, waitForServerState, framesDrawn,
} from './harness.mjs';

// lavapipe on two cores draws a few frames a second at 96x64; the first can take seconds more.
const FIRST_FRAME_MS = 30_000;
const FRAME_MS = 15_000;
const STATE_MS = 10_000;
const TEST_MS = 60_000;

const KEY_HOLD_MS = 500; // W (with Shift) is held this long, and for at least this many frames:
const KEY_HOLD_MIN_FRAMES = 3;
// A picture changed "substantially" when its 8x8-block means differ by several times what two
// frames at rest differ by (the renderer's noise), and never by less than a floor in 0..255
// levels: a converged picture at rest can differ by almost nothing.
const MOVE_NOISE_FACTOR = 4;
const MOVE_FLOOR_LEVELS = 2;
const DEBUG_VIEW_NOISE_FACTOR = 8;
const DEBUG_VIEW_FLOOR_LEVELS = 15;
const WALL_COLOUR_MARGIN = 5; // levels by which the red wall's third must be redder than green

const problem = await missingPrerequisite();
if (problem && process.env.CI) {
  test('the browser tests can run', () => assert.fail(problem));
} else {
  if (problem) console.log(`penumbra browser tests skipped: ${problem}`);
  describe('penumbra serve in a browser', { skip: problem ?? false, timeout: 240_000 }, defineTests);
  describe('penumbra serve --token', { skip: problem ?? false, timeout: 120_000 }, defineTokenTests);
}

// A test whose failure says what the server logged last.
function testWithServerLog(name, currentServer, body) {
  test(name, { timeout: TEST_MS }, async (t) => {
    try {
      await body(t);
    } catch (error) {
      error.message += `\n--- the server's last lines ---\n${currentServer()?.logTail() ?? '(no server)'}`;
      throw error;
    }
  });
}

function defineTests() {
  let server;
  let browser;
  let page;
  const pageErrors = [];
  let restNoise = 0; // measured by the key test, used by the settings test

  before(async () => {
    server = await startServer();
    browser = await launchBrowser();
    page = await openPage(server.httpUrl);
    await makePlaying(page);
  }, { timeout: 90_000 });

  after(async () => {
    await browser?.close().catch(() => {});
    await server?.stop();
  }, { timeout: 20_000 });

  // Opens a URL in a fresh browser context and waits for the element's hello.
  async function openPage(url) {
    const context = await browser.newContext({ viewport: { width: 640, height: 480 } });
    const newPage = await context.newPage();
    newPage.on('pageerror', (error) => pageErrors.push(`${url}: ${error.message}`));
    await newPage.goto(url, { timeout: STATE_MS });
    await waitForServerState(newPage, () => true, STATE_MS, 'hello');
    return newPage;
  }

  // The server starts paused, as the desktop viewer does; paused, the camera does not move.
  async function makePlaying(target) {
    const hello = await target.evaluate(() => document.querySelector('penumbra-view').hello);
    if (hello.settings?.playing === true) return;
    await target.evaluate(() => document.querySelector('penumbra-view').set('playing', true));
    await waitForServerState(target, (s) => s.settings?.playing === true || s.playing === true, STATE_MS);
  }

  const serverTest = (name, body) => testWithServerLog(name, () => server, body);

  function assertNoPageErrors() {
    assert.deepEqual(pageErrors, [], 'uncaught errors in the page');
  }

  serverTest('the page shows the Cornell box: red wall left, green wall right', async () => {
    await waitForFramesDrawn(page, 1, FIRST_FRAME_MS);
    const picture = await readCanvas(page);
    await savePicture(page, 'cornell');
    assert.equal(picture.width, 96);
    assert.equal(picture.height, 64);
    const third = Math.floor(picture.width / 3);
    const [leftRed, leftGreen] = meanColour(picture, 0, third);
    const [rightRed, rightGreen] = meanColour(picture, picture.width - third, picture.width);
    assert.ok(leftRed > leftGreen + WALL_COLOUR_MARGIN,
      `left third red ${leftRed.toFixed(1)} should exceed its green ${leftGreen.toFixed(1)}`);
    assert.ok(rightGreen > rightRed + WALL_COLOUR_MARGIN,
      `right third green ${rightGreen.toFixed(1)} should exceed its red ${rightRed.toFixed(1)}`);

    // The stats event carries the client's own figures next to the server's.
    const stats = await waitForServerState(page, (s) => s.clientFps > 0 && s.mbits > 0, STATE_MS);
    assert.equal(typeof stats.renderMs, 'number');
    assert.ok('latencyMs' in stats);
    assert.equal(await page.evaluate(() => document.querySelector('penumbra-view').connected), true);
    assertNoPageErrors();
  });

  serverTest('holding Shift+W moves the camera', async (t) => {
    const rest = [await nextPicture(page, FRAME_MS)];
    for (let i = 0; i < 2; i++) rest.push(await nextPicture(page, FRAME_MS));
    restNoise = Math.max(pictureDifference(rest[0], rest[1]), pictureDifference(rest[1], rest[2]));
    const before = rest[2];
    const statsBefore = await page.evaluate(() => document.querySelector('penumbra-view').stats);

    await page.locator('penumbra-view').focus();
    // Held for half a second and for at least a few frames: the server moves the camera by each
    // frame's time but by at most a quarter second a frame, so on a slow machine time alone
    // would move it less.
    const framesAtPress = await framesDrawn(page);
    await page.keyboard.down('ShiftLeft'); // four times the speed: well above the noise
    await page.keyboard.down('KeyW');
    await page.waitForTimeout(KEY_HOLD_MS);
    await waitForFramesDrawn(page, framesAtPress + KEY_HOLD_MIN_FRAMES - 1, FRAME_MS);
    await page.keyboard.up('KeyW');
    await page.keyboard.up('ShiftLeft');
    // The frame after the one that saw the key go up shows where the camera stopped.
    await waitForServerState(page, (s) => typeof s.latencyMs === 'number', FRAME_MS);
    const moved = await nextPicture(page, FRAME_MS, 2);
    await savePicture(page, 'moved');

    const difference = pictureDifference(before, moved);
    const required = Math.max(MOVE_NOISE_FACTOR * restNoise, MOVE_FLOOR_LEVELS);
    t.diagnostic(`rest noise ${restNoise.toFixed(2)}, moved ${difference.toFixed(2)} levels (required > ${required.toFixed(2)})`);
    assert.ok(difference > required, `moving changed the picture by ${difference.toFixed(2)} levels; ` +
      `at rest it changes by ${restNoise.toFixed(2)}; required > ${required.toFixed(2)}`);

    const statsAfter = await waitForServerState(page, (s) => s.latencyMs > 0, STATE_MS);
    // The server reports the camera's position in stats (beyond docs/SERVE.md's list); where it
    // does, the position must have moved too.
    if (Array.isArray(statsBefore?.camera)) {
      const travelled = Math.hypot(...statsAfter.camera.map((c, i) => c - statsBefore.camera[i]));
      assert.ok(travelled > 0, `stats.camera did not move: ${JSON.stringify(statsAfter.camera)}`);
    }

    // R puts the camera back for the tests that follow.
    await page.keyboard.press('KeyR');
    await nextPicture(page, FRAME_MS, 2);
    assertNoPageErrors();
  });

  serverTest('a setting changed in the panel reaches the renderer and comes back', async (t) => {
    const hello = await page.evaluate(() => document.querySelector('penumbra-view').hello);
    assert.ok(Array.isArray(hello.debugViews) && hello.debugViews.includes('normals'),
      `hello.debugViews ${JSON.stringify(hello.debugViews)} should offer normals`);
    const beauty = await nextPicture(page, FRAME_MS);

    // Through the page's own control: the select is filled from hello.debugViews.
    await page.selectOption('#debug', 'normals');
    await waitForServerState(page, (s) => s.settings?.debug === 'normals', STATE_MS);
    const normals = await nextPicture(page, FRAME_MS, 2);
    await savePicture(page, 'normals');
    const difference = pictureDifference(beauty, normals);
    const required = Math.max(DEBUG_VIEW_NOISE_FACTOR * restNoise, DEBUG_VIEW_FLOOR_LEVELS);
    t.diagnostic(`normals differ from beauty by ${difference.toFixed(2)} levels (required > ${required.toFixed(2)})`);
    assert.ok(difference > required, `the normals view differs from the beauty render by ` +
      `${difference.toFixed(2)} levels; required > ${required.toFixed(2)}`);

    // Through the element's API; the panel follows the server's settings.
    await page.evaluate(() => document.querySelector('penumbra-view').set('debug', 'none'));
    await waitForServerState(page, (s) => s.settings?.debug === 'none', STATE_MS);
    await page.waitForFunction(() => document.getElementById('debug').value === 'none', null,
      { timeout: STATE_MS });
    const back = await nextPicture(page, FRAME_MS, 2);
    const backDifference = pictureDifference(beauty, back);
    t.diagnostic(`back to beauty: ${backDifference.toFixed(2)} levels from the first beauty picture`);
    assert.ok(backDifference < difference / 2, `back from normals the picture still differs by ` +
      `${backDifference.toFixed(2)} levels from the beauty render (normals: ${difference.toFixed(2)})`);
    assertNoPageErrors();
  });

  serverTest('two browsers at once both receive frames', async () => {
    const second = await openPage(server.httpUrl);
    try {
      const firstStart = await framesDrawn(page);
      await waitForFramesDrawn(second, 2, FIRST_FRAME_MS);
      await waitForFramesDrawn(page, firstStart + 2, FRAME_MS);
      const stats = await waitForServerState(second, (s) => s.clients >= 2, STATE_MS);
      assert.ok(stats.clients >= 2);
    } finally {
      await second.context().close();
    }
    assertNoPageErrors();
  });

  serverTest('the embed example works from a page of its own origin', async () => {
    // The example names the server's default address; the copy served here names this test's
    // server, from which it loads the element's script too (cross-origin, like the WebSocket).
    const pages = await startStaticServer((name, text) => name === 'embed-example.html'
      ? text.replaceAll('127.0.0.1:8080', `127.0.0.1:${server.port}`)
      : text);
    try {
      const embedded = await openPage(`${pages.url}embed-example.html`);
      try {
        await waitForFramesDrawn(embedded, 2, FIRST_FRAME_MS);
        const picture = await readCanvas(embedded);
        const [leftRed, leftGreen] = meanColour(picture, 0, Math.floor(picture.width / 3));
        assert.ok(leftRed > leftGreen, 'the embedded picture should show the red wall on the left');
        // The element keeps the picture's aspect ratio in the width the page gave it.
        const box = await embedded.locator('penumbra-view').boundingBox();
        const expectedHeight = box.width * picture.height / picture.width;
        assert.ok(Math.abs(box.height - expectedHeight) <= 2,
          `element ${box.width}x${box.height}, expected height ${expectedHeight.toFixed(1)}`);
      } finally {
        await embedded.context().close();
      }
    } finally {
      await pages.close();
    }
    assertNoPageErrors();
  });
}

// The page takes ?token= from its own address and hands it to the element's WebSocket.
function defineTokenTests() {
  const token = 'browser-test-secret';
  let server;
  let browser;
  const serverTest = (name, body) => testWithServerLog(name, () => server, body);

  before(async () => {
    server = await startServer(['--token', token]);
    browser = await launchBrowser();
  }, { timeout: 90_000 });

  after(async () => {
    await browser?.close().catch(() => {});
    await server?.stop();
  }, { timeout: 20_000 });

  serverTest('the page opened with ?token= draws frames', async () => {
    const context = await browser.newContext({ viewport: { width: 320, height: 240 } });
    try {
      const page = await context.newPage();
      await page.goto(`${server.httpUrl}?token=${token}`, { timeout: STATE_MS });
      await waitForFramesDrawn(page, 0, FIRST_FRAME_MS);
      const denied = await page.evaluate(async (url) => (await fetch(url)).status, server.httpUrl);
      assert.notEqual(denied, 200, 'the page without the token should be refused');
    } finally {
      await context.close();
    }
  });
}
