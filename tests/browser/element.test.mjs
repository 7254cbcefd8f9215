// <penumbra-view> and the page against a scripted server: Playwright answers the element's
// WebSocket itself, so these tests see every message the element sends (which the real server
// only shows as its effects) and can send it frames and replies of their choosing.
import assert from 'node:assert/strict';
import { after, before, beforeEach, describe, test } from 'node:test';

import { launchBrowser, missingPrerequisite, startStaticServer } from './harness.mjs';

const WAIT_MS = 5_000;
const TEST_MS = 20_000;
const PICTURE_WIDTH = 96;
const PICTURE_HEIGHT = 64;

const problem = await missingPrerequisite({ needsServer: false });
if (problem && process.env.CI) {
  test('the browser tests can run', () => assert.fail(problem));
} else {
  if (problem) console.log(`penumbra browser tests skipped: ${problem}`);
  describe('<penumbra-view> against a scripted server', { skip: problem ?? false, timeout: 120_000 }, defineTests);
}

// One scripted connection: what the element sent, and a way to answer.
class ScriptedSocket {
  constructor(route) {
    this.route = route;
    this.url = route.url();
    this.received = [];
    this.waiters = [];
    route.onMessage((message) => this.onMessage(message));
  }

  onMessage(message) {
    if (typeof message !== 'string') return;
    this.received.push(JSON.parse(message));
    for (const waiter of [...this.waiters]) waiter();
  }

  send(message) {
    this.route.send(typeof message === 'string' || Buffer.isBuffer(message) ? message : JSON.stringify(message));
  }

  // Input messages (everything but acks) received so far.
  inputs() {
    return this.received.filter((m) => m.t !== 'ack');
  }

  // Resolves with the first received message (from index `from`) that satisfies `accept`.
  waitFor(accept, what, from = 0) {
    return new Promise((resolve, reject) => {
      const check = () => {
        const found = this.received.slice(from).find(accept);
        if (!found) return false;
        clearTimeout(timer);
        this.waiters = this.waiters.filter((w) => w !== check);
        resolve(found);
        return true;
      };
      const timer = setTimeout(() => {
        this.waiters = this.waiters.filter((w) => w !== check);
        reject(new Error(`no ${what} within ${WAIT_MS} ms; received ${JSON.stringify(this.received.slice(-12))}`));
      }, WAIT_MS);
      if (!check()) this.waiters.push(check);
    });
  }
}

function helloMessage(overrides = {}) {
  return {
    t: 'hello', scene: 'scripted', width: PICTURE_WIDTH, height: PICTURE_HEIGHT,
    settings: { spp: 2, bounces: 4, scale: 1, temporal: true, denoise: 0, debug: 'none',
      debugOpacity: 1, torch: false, exposure: 0, playing: true },
    debugViews: ['none', 'normals', 'albedo'], walking: false, canWalk: false, hasTorch: true,
    controls: '', ...overrides,
  };
}

// A frame message as docs/SERVE.md lays it out, with each JPEG as one strip.
function frameMessage({ number, ackSeq = 0, strips }) {
  const stripBytes = strips.reduce((sum, s) => sum + 8 + s.jpeg.length, 0);
  const message = Buffer.alloc(32 + stripBytes);
  message.writeUInt32LE(0x31464e50, 0);
  message.writeUInt32LE(number, 4);
  message.writeUInt16LE(PICTURE_WIDTH, 8);
  message.writeUInt16LE(PICTURE_HEIGHT, 10);
  message.writeUInt32LE(ackSeq, 12);
  message.writeFloatLE(4.5, 16);
  message.writeFloatLE(1.25, 20);
  message.writeUInt32LE(85, 24);
  message.writeUInt32LE(strips.length, 28);
  let at = 32;
  for (const strip of strips) {
    message.writeUInt16LE(strip.y, at);
    message.writeUInt16LE(strip.rows, at + 2);
    message.writeUInt32LE(strip.jpeg.length, at + 4);
    strip.jpeg.copy(message, at + 8);
    at += 8 + strip.jpeg.length;
  }
  return message;
}

function defineTests() {
  let browser;
  let pages;
  let strips; // the top half red, the bottom half blue, as two JPEG strips
  let page;
  let sockets;

  before(async () => {
    browser = await launchBrowser();
    pages = await startStaticServer();
    strips = await makeStrips();
  }, { timeout: 60_000 });

  after(async () => {
    await browser?.close().catch(() => {});
    await pages?.close();
  });

  beforeEach(async () => {
    await page?.context().close();
    page = null;
    sockets = [];
  });

  // The browser's own JPEG encoder makes the strips: no image library needed here.
  async function makeStrips() {
    const scratch = await browser.newPage();
    const encode = (colour, rows) => scratch.evaluate(async ([fill, width, height]) => {
      const canvas = new OffscreenCanvas(width, height);
      const context = canvas.getContext('2d');
      context.fillStyle = fill;
      context.fillRect(0, 0, width, height);
      const blob = await canvas.convertToBlob({ type: 'image/jpeg', quality: 0.9 });
      return Array.from(new Uint8Array(await blob.arrayBuffer()));
    }, [colour, PICTURE_WIDTH, rows]);
    const half = PICTURE_HEIGHT / 2;
    const made = [
      { y: 0, rows: half, jpeg: Buffer.from(await encode('#ff0000', half)) },
      { y: half, rows: half, jpeg: Buffer.from(await encode('#0000ff', half)) },
    ];
    await scratch.close();
    return made;
  }

  // Opens the page with every /ws connection answered by a ScriptedSocket that says hello.
  async function openPage(query = '', hello = helloMessage()) {
    const context = await browser.newContext({ viewport: { width: 640, height: 480 } });
    page = await context.newPage();
    await page.routeWebSocket(/\/ws(\?|$)/, (route) => {
      const socket = new ScriptedSocket(route);
      sockets.push(socket);
      socket.send(hello);
    });
    await page.goto(`${pages.url}index.html${query}`, { timeout: WAIT_MS });
    await page.waitForFunction(() => document.querySelector('penumbra-view')?.hello, null, { timeout: WAIT_MS });
    return sockets[sockets.length - 1];
  }

  async function sendFrameAndWaitForAck(socket, number, ackSeq = 0) {
    const from = socket.received.length;
    socket.send(frameMessage({ number, ackSeq, strips }));
    await socket.waitFor((m) => m.t === 'ack' && m.frame === number, `ack of frame ${number}`, from);
  }

  test("draws a frame's strips at their rows and acknowledges it", { timeout: TEST_MS }, async () => {
    const socket = await openPage();
    const frameEvents = page.evaluate(() => new Promise((resolve) => {
      document.querySelector('penumbra-view').addEventListener('frame', (e) => resolve(e.detail), { once: true });
    }));
    await sendFrameAndWaitForAck(socket, 7);
    assert.equal(await frameEvents, 7);
    const colours = await page.evaluate(() => {
      const canvas = document.querySelector('penumbra-view').shadowRoot.querySelector('canvas');
      const context = canvas.getContext('2d');
      const at = (x, y) => Array.from(context.getImageData(x, y, 1, 1).data.slice(0, 3));
      return { width: canvas.width, height: canvas.height, top: at(48, 10), bottom: at(48, 54) };
    });
    assert.equal(colours.width, PICTURE_WIDTH);
    assert.equal(colours.height, PICTURE_HEIGHT);
    assert.ok(colours.top[0] > 200 && colours.top[2] < 60, `top strip should be red: ${colours.top}`);
    assert.ok(colours.bottom[2] > 200 && colours.bottom[0] < 60, `bottom strip should be blue: ${colours.bottom}`);

    // A frame older than one already drawn is not drawn and not acknowledged again.
    const from = socket.received.length;
    socket.send(frameMessage({ number: 5, strips }));
    await sendFrameAndWaitForAck(socket, 8);
    assert.deepEqual(socket.received.slice(from).filter((m) => m.t === 'ack').map((m) => m.frame), [8]);
  });

  test('keys go to the server once per press and are released on blur', { timeout: TEST_MS }, async () => {
    const socket = await openPage();
    await page.locator('penumbra-view').focus();
    await page.keyboard.down('KeyW');
    await page.keyboard.down('KeyW'); // Playwright marks this one as a repeat
    await page.keyboard.up('KeyW');
    await page.keyboard.down('KeyA');
    await socket.waitFor((m) => m.t === 'key' && m.code === 'KeyA' && m.down, 'KeyA down');
    await page.locator('#panel-toggle').focus(); // the element loses the focus while A is held
    await socket.waitFor((m) => m.t === 'key' && m.code === 'KeyA' && !m.down, 'KeyA up on blur');
    await page.keyboard.up('KeyA');
    await page.keyboard.press('KeyD'); // the element has no focus now: not sent

    const keys = socket.inputs().filter((m) => m.t === 'key').map((m) => `${m.code} ${m.down ? 'down' : 'up'}`);
    assert.deepEqual(keys, ['KeyW down', 'KeyW up', 'KeyA down', 'KeyA up']);
    const seqs = socket.inputs().map((m) => m.seq);
    assert.ok(seqs.every((seq, i) => Number.isInteger(seq) && seq > 0 && (i === 0 || seq > seqs[i - 1])),
      `seqs must increase: ${seqs}`);
  });

  test('mouse: click, drag, right-drag look and wheel', { timeout: TEST_MS }, async () => {
    const socket = await openPage();
    await sendFrameAndWaitForAck(socket, 1); // the canvas takes the picture's size
    // The view fills 640x480; the 3:2 picture is 640 wide, centred: rows 26.7..453.3.
    const pictureTop = (480 - 640 * PICTURE_HEIGHT / PICTURE_WIDTH) / 2;
    const toPicture = (x, y) => ({ x: x / 640, y: (y - pictureTop) / (480 - 2 * pictureTop) });

    // A press and release that moves less than 4 px is a click (after grab and release).
    await page.mouse.move(200, 240);
    await page.mouse.down();
    await page.mouse.move(202, 241);
    await page.mouse.up();
    const click = await socket.waitFor((m) => m.t === 'click', 'click');
    const expected = toPicture(202, 241);
    assert.ok(Math.abs(click.x - expected.x) < 0.01 && Math.abs(click.y - expected.y) < 0.01,
      `click at ${JSON.stringify(click)}, expected about ${JSON.stringify(expected)}`);
    assert.deepEqual(socket.inputs().map((m) => m.t), ['grab', 'release', 'click']);
    assert.equal(socket.inputs()[0].turn, false);

    // A drag: grab (with Shift: turn), drags, release, and no click.
    let from = socket.received.length;
    await page.keyboard.down('Shift');
    await page.mouse.down();
    await page.mouse.move(260, 240, { steps: 5 });
    await page.mouse.up();
    await page.keyboard.up('Shift');
    await socket.waitFor((m) => m.t === 'release', 'release after a drag', from);
    const dragMessages = socket.received.slice(from).filter((m) => m.t !== 'ack' && m.t !== 'key');
    const kinds = dragMessages.map((m) => m.t);
    assert.equal(kinds[0], 'grab');
    assert.equal(dragMessages[0].turn, true);
    assert.equal(kinds[kinds.length - 1], 'release');
    assert.ok(kinds.includes('drag') && !kinds.includes('click'), `drag messages: ${kinds}`);
    const lastDrag = dragMessages.filter((m) => m.t === 'drag').pop();
    assert.ok(Math.abs(lastDrag.x - toPicture(260, 240).x) < 0.01, `last drag at ${lastDrag.x}`);

    // Right button drag looks around; motion within a frame is summed.
    from = socket.received.length;
    await page.mouse.down({ button: 'right' });
    await page.mouse.move(290, 250, { steps: 6 });
    await page.mouse.up({ button: 'right' });
    await page.waitForTimeout(100); // the last animation frame's sum
    const looks = socket.received.slice(from).filter((m) => m.t === 'look');
    const sum = looks.reduce((s, m) => ({ dx: s.dx + m.dx, dy: s.dy + m.dy }), { dx: 0, dy: 0 });
    assert.ok(looks.length >= 1 && Math.abs(sum.dx - 30) <= 2 && Math.abs(sum.dy - 10) <= 2,
      `look messages ${JSON.stringify(looks)} should add up to 30, 10`);
    assert.ok(!socket.received.slice(from).some((m) => m.t === 'grab' || m.t === 'click'));

    // Scrolling up one notch: faster.
    from = socket.received.length;
    await page.mouse.wheel(0, -100);
    const wheel = await socket.waitFor((m) => m.t === 'wheel', 'wheel', from);
    assert.equal(wheel.dy, 1);
  });

  test('input-to-frame latency, client figures in stats, and the panel', { timeout: TEST_MS }, async () => {
    const socket = await openPage();
    await page.locator('penumbra-view').focus();
    await page.keyboard.press('KeyP');
    const up = await socket.waitFor((m) => m.t === 'key' && !m.down, 'key up');
    await sendFrameAndWaitForAck(socket, 1, up.seq);
    const statsEvent = page.evaluate(() => new Promise((resolve) => {
      document.querySelector('penumbra-view').addEventListener('stats', (e) => resolve(e.detail), { once: true });
    }));
    const settings = { ...helloMessage().settings, exposure: 2.5, debug: 'albedo', spp: 8 };
    socket.send({ t: 'stats', fps: 1, renderMs: 4.5, encodeMs: 1.25, spp: 8, width: PICTURE_WIDTH,
      height: PICTURE_HEIGHT, clients: 1, walking: false, playing: true, settings, message: 'Tall box' });
    const stats = await statsEvent;
    assert.ok(stats.latencyMs > 0 && stats.latencyMs < WAIT_MS, `latencyMs ${stats.latencyMs}`);
    assert.ok(stats.clientFps >= 1, `clientFps ${stats.clientFps}`);
    assert.ok(stats.mbits > 0, `mbits ${stats.mbits}`);
    assert.equal(stats.message, 'Tall box');

    // The panel reflects the server's settings and sends the user's.
    assert.equal(await page.inputValue('#exposure'), '2.5');
    assert.equal(await page.inputValue('#spp'), '8');
    assert.equal(await page.inputValue('#debug'), 'albedo');
    assert.equal(await page.textContent('#message'), 'Tall box');
    await page.selectOption('#debug', 'normals');
    await socket.waitFor((m) => m.t === 'set' && m.name === 'debug' && m.value === 'normals', 'set debug');
    await page.click('#panel-toggle');
    assert.equal(await page.isHidden('#panel'), true, 'the settings button hides the panel');
  });

  test('the token goes to the WebSocket and the element reconnects after a drop', { timeout: TEST_MS }, async () => {
    const first = await openPage('?token=s3cret');
    assert.equal(new URL(first.url).searchParams.get('token'), 's3cret');
    assert.equal(new URL(first.url).pathname, '/ws');
    first.route.close();
    await page.waitForFunction(() => document.querySelector('penumbra-view').connected === false, null,
      { timeout: WAIT_MS });
    await page.waitForFunction(() => document.querySelector('penumbra-view').connected === true, null,
      { timeout: WAIT_MS });
    assert.equal(sockets.length, 2);
    assert.equal(new URL(sockets[1].url).searchParams.get('token'), 's3cret');
    await sendFrameAndWaitForAck(sockets[1], 1); // frame numbers start again on a new connection
  });

  test('walking: a click asks for the pointer lock, and locked motion looks around', { timeout: TEST_MS }, async () => {
    const socket = await openPage('', helloMessage({ walking: true, canWalk: true }));
    await sendFrameAndWaitForAck(socket, 1);
    await page.mouse.click(200, 240);
    await page.waitForFunction(() => document.pointerLockElement === document.querySelector('penumbra-view'),
      null, { timeout: WAIT_MS });
    assert.ok(!socket.inputs().some((m) => m.t === 'click' || m.t === 'grab'), 'walking: no click or grab');
    await page.mouse.move(220, 250, { steps: 4 });
    await socket.waitFor((m) => m.t === 'look', 'look while locked');
  });
}
