// <penumbra-view>: shows a `penumbra serve` picture and sends the viewer's input back.
// The protocol it speaks is docs/SERVE.md. One plain ES module, no dependencies, no build step:
//   <script type="module" src="/penumbra-view.js"></script>
//   <penumbra-view server="ws://host:8080/ws" token="secret" overlay></penumbra-view>

const FRAME_MAGIC = 0x31464e50; // the bytes "PNF1" read as a little-endian u32
const FRAME_HEADER_BYTES = 32;
const STRIP_HEADER_BYTES = 8;

const CLICK_SLOP_PX = 4; // a left press and release closer than this is a click, not a drag
const RECONNECT_FIRST_MS = 250;
const RECONNECT_MAX_MS = 5000;
const FIGURE_WINDOW_MS = 1000; // fps and Mbit/s are measured over the last second
const LATENCY_SMOOTHING = 0.2; // weight of a new sample in the running latency figure
const PENDING_SEQ_LIMIT = 512; // seqs awaiting a frame; older ones are forgotten

// Keys the browser keeps: Escape releases the pointer lock (and the desktop viewer quits on it),
// Tab moves the focus on (the desktop viewer's panel key; the server has no panel), F5 reloads,
// F11 is full screen, F12 the developer tools.
const BROWSER_KEYS = new Set(['Escape', 'Tab', 'F5', 'F11', 'F12']);

// Parses one binary frame message. Returns null when it is not a well-formed frame.
export function parseFrame(buffer) {
  if (buffer.byteLength < FRAME_HEADER_BYTES) return null;
  const view = new DataView(buffer);
  if (view.getUint32(0, true) !== FRAME_MAGIC) return null;
  const frame = {
    number: view.getUint32(4, true),
    width: view.getUint16(8, true),
    height: view.getUint16(10, true),
    ackSeq: view.getUint32(12, true),
    gpuMs: view.getFloat32(16, true),
    encodeMs: view.getFloat32(20, true),
    quality: view.getUint32(24, true),
    strips: [],
  };
  const stripCount = view.getUint32(28, true);
  let offset = FRAME_HEADER_BYTES;
  for (let i = 0; i < stripCount; i++) {
    if (offset + STRIP_HEADER_BYTES > buffer.byteLength) return null;
    const y = view.getUint16(offset, true);
    const rows = view.getUint16(offset + 2, true);
    const bytes = view.getUint32(offset + 4, true);
    offset += STRIP_HEADER_BYTES;
    if (offset + bytes > buffer.byteLength) return null;
    frame.strips.push({ y, rows, jpeg: new Uint8Array(buffer, offset, bytes) });
    offset += bytes;
  }
  return frame;
}

// The WebSocket URL for a `server` attribute: ws(s) URLs as given, http(s) URLs get the
// matching ws scheme and the path /ws; no attribute means this page's own origin.
export function webSocketUrl(serverAttribute, token, baseHref = globalThis.location.href) {
  const url = new URL(serverAttribute || '/ws', baseHref);
  if (url.protocol === 'http:' || url.protocol === 'https:') {
    url.protocol = url.protocol === 'https:' ? 'wss:' : 'ws:';
    // An http(s) URL names the server; its WebSocket lives at /ws under it.
    if (!url.pathname.endsWith('/ws')) url.pathname = url.pathname.replace(/\/?$/, '/ws');
  }
  if (token) url.searchParams.set('token', token);
  url.hash = '';
  return url.href;
}

// Counts events (or amounts) over a sliding window of time.
class SlidingSum {
  constructor(windowMs) {
    this.windowMs = windowMs;
    this.entries = [];
  }
  add(amount, now = performance.now()) {
    this.entries.push([now, amount]);
    this.trim(now);
  }
  trim(now) {
    while (this.entries.length && now - this.entries[0][0] > this.windowMs) this.entries.shift();
  }
  perSecond(now = performance.now()) {
    this.trim(now);
    let sum = 0;
    for (const [, amount] of this.entries) sum += amount;
    return (sum * 1000) / this.windowMs;
  }
}

const TEMPLATE = `
<style>
  :host { display: block; position: relative; overflow: hidden; background: #000; outline: none; }
  :host(:focus-visible) { box-shadow: inset 0 0 0 2px #4a90e2; }
  /* object-fit keeps the picture's aspect ratio inside whatever box the page gives the element;
     with no height given, the canvas's own ratio sets the element's height. */
  canvas { display: block; width: 100%; height: 100%; object-fit: contain; }
  .overlay { position: absolute; top: 6px; left: 6px; padding: 3px 6px; border-radius: 4px;
             background: rgba(0,0,0,.55); color: #eee; font: 11px/1.35 ui-monospace, monospace;
             pointer-events: none; white-space: pre; max-width: calc(100% - 24px);
             overflow: hidden; text-overflow: ellipsis; }
  .notice { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
            color: #bbb; font: 13px sans-serif; pointer-events: none; }
  [hidden] { display: none !important; }
</style>
<canvas width="1" height="1"></canvas>
<div class="overlay" hidden></div>
<div class="notice">connecting…</div>
`;

export class PenumbraView extends HTMLElement {
  static get observedAttributes() {
    return ['server', 'token', 'overlay'];
  }

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML = TEMPLATE;
    this.canvas = root.querySelector('canvas');
    this.context2d = this.canvas.getContext('2d');
    this.overlayBox = root.querySelector('.overlay');
    this.noticeBox = root.querySelector('.notice');

    this.started = false; // between connectedCallback and disconnectedCallback
    this.socket = null;
    this.connectionId = 0; // frames decoded for an older socket are thrown away
    this.reconnectTimer = 0;
    this.reconnectAttempts = 0;
    this.socketOpen = false;
    this.latestHello = null;
    this.latestStats = null;
    this.walking = false;

    this.lastDrawnFrame = -1;
    this.lastAckedFrame = -1;
    this.framesDrawnCount = 0;
    this.drawTimes = new SlidingSum(FIGURE_WINDOW_MS);
    this.bytesReceived = new SlidingSum(FIGURE_WINDOW_MS);

    this.nextSeq = 1;
    this.seqSendTimes = new Map(); // seq -> performance.now() when sent
    this.latency = null;

    this.heldKeys = new Set();
    this.leftPress = null; // {startX, startY, moved} while the left button is down (not walking)
    this.rightDrag = false;
    this.pending = { lookX: 0, lookY: 0, drag: null, wheel: 0 };
    this.wheelRemainder = 0;
    this.flushScheduled = false;

    this.bindHandlers();
  }

  // ---- public API ----

  get hello() { return this.latestHello; }
  get stats() { return this.latestStats; }
  get connected() { return this.socketOpen; }
  get framesDrawn() { return this.framesDrawnCount; }

  // Sends a `set` message; returns false when not connected (nothing is queued).
  set(name, value) {
    return this.sendInput({ t: 'set', name, value });
  }

  // ---- lifecycle ----

  connectedCallback() {
    // Attributes present at upgrade are reported before this; only later changes reconnect.
    this.started = true;
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    this.addListeners();
    this.updateOverlayVisibility();
    this.connect();
  }

  disconnectedCallback() {
    this.started = false;
    this.releaseAllKeys();
    this.removeListeners();
    this.disconnect();
  }

  attributeChangedCallback(name, oldValue, newValue) {
    if (oldValue === newValue) return;
    if (name === 'overlay') {
      this.updateOverlayVisibility();
    } else if (this.started) {
      this.connect(); // a new address or token: a new connection
    }
  }

  // ---- connection ----

  connect() {
    this.disconnect();
    const id = this.connectionId;
    let socket;
    try {
      socket = new WebSocket(webSocketUrl(this.getAttribute('server'), this.getAttribute('token')));
    } catch (error) {
      console.warn('penumbra-view: cannot open the WebSocket:', error);
      this.scheduleReconnect();
      return;
    }
    socket.binaryType = 'arraybuffer';
    socket.onopen = () => {
      if (id !== this.connectionId) return;
      this.resetPerConnectionState();
      this.setConnected(true);
    };
    socket.onmessage = (event) => {
      if (id === this.connectionId) this.onSocketMessage(event.data, id);
    };
    socket.onclose = () => {
      if (id !== this.connectionId) return;
      this.socket = null;
      this.setConnected(false);
      this.scheduleReconnect();
    };
    this.socket = socket;
  }

  disconnect() {
    clearTimeout(this.reconnectTimer);
    this.connectionId++;
    if (this.socket) {
      this.socket.onclose = null;
      this.socket.close();
      this.socket = null;
    }
    this.setConnected(false);
  }

  scheduleReconnect() {
    if (!this.started) return; // the element left the page
    const delay = Math.min(RECONNECT_MAX_MS, RECONNECT_FIRST_MS * 2 ** this.reconnectAttempts);
    this.reconnectAttempts++;
    // A little jitter so that many pages do not all come back in the same instant.
    this.reconnectTimer = setTimeout(() => this.connect(), delay * (0.8 + 0.4 * Math.random()));
  }

  // Frame numbers and seqs start again with a new connection (the server may have restarted).
  resetPerConnectionState() {
    this.lastDrawnFrame = -1;
    this.lastAckedFrame = -1;
    this.seqSendTimes.clear();
    this.heldKeys.clear();
  }

  setConnected(connected) {
    if (this.socketOpen === connected) return;
    this.socketOpen = connected;
    this.noticeBox.hidden = connected;
    this.noticeBox.textContent = connected ? '' : 'connecting…';
    this.dispatchEvent(new CustomEvent('connection', { detail: { connected } }));
  }

  send(message) {
    if (!this.socket || this.socket.readyState !== WebSocket.OPEN) return false;
    this.socket.send(JSON.stringify(message));
    return true;
  }

  // Input messages carry an increasing seq; the time each was sent measures input-to-frame latency.
  sendInput(message) {
    const seq = this.nextSeq;
    if (!this.send({ ...message, seq })) return false;
    this.nextSeq++;
    this.seqSendTimes.set(seq, performance.now());
    if (this.seqSendTimes.size > PENDING_SEQ_LIMIT) {
      this.seqSendTimes.delete(this.seqSendTimes.keys().next().value);
    }
    return true;
  }

  // ---- messages from the server ----

  onSocketMessage(data, id) {
    if (typeof data === 'string') {
      this.bytesReceived.add(data.length);
      this.onTextMessage(data);
    } else {
      this.bytesReceived.add(data.byteLength);
      this.onFrameMessage(data, id);
    }
  }

  onTextMessage(text) {
    let message;
    try {
      message = JSON.parse(text);
    } catch {
      console.warn('penumbra-view: a text message that is not JSON:', text.slice(0, 200));
      return;
    }
    if (message.t === 'hello') this.onHello(message);
    else if (message.t === 'stats') this.onStats(message);
  }

  onHello(hello) {
    this.reconnectAttempts = 0; // the server answered: the next drop starts the backoff afresh
    this.latestHello = hello;
    this.setWalking(Boolean(hello.walking));
    // Until the first frame, the empty canvas takes the picture's size, so the element's box
    // has the right aspect ratio from the start.
    if (this.framesDrawnCount === 0 && hello.width > 0 && hello.height > 0) {
      this.canvas.width = hello.width;
      this.canvas.height = hello.height;
    }
    this.dispatchEvent(new CustomEvent('hello', { detail: hello }));
  }

  onStats(serverStats) {
    const now = performance.now();
    const stats = {
      ...serverStats,
      clientFps: this.drawTimes.perSecond(now),
      mbits: (this.bytesReceived.perSecond(now) * 8) / 1e6,
      latencyMs: this.latency,
    };
    this.latestStats = stats;
    if ('walking' in stats) this.setWalking(Boolean(stats.walking));
    this.renderOverlay();
    this.dispatchEvent(new CustomEvent('stats', { detail: stats }));
  }

  setWalking(walking) {
    this.walking = walking;
    if (!walking && document.pointerLockElement === this) document.exitPointerLock();
  }

  async onFrameMessage(buffer, id) {
    const frame = parseFrame(buffer);
    if (!frame) {
      console.warn('penumbra-view: a binary message that is not a frame was dropped');
      return;
    }
    let bitmaps;
    try {
      bitmaps = await Promise.all(frame.strips.map((strip) =>
        createImageBitmap(new Blob([strip.jpeg], { type: 'image/jpeg' }))));
    } catch (error) {
      console.warn(`penumbra-view: frame ${frame.number} did not decode:`, error);
      // Acknowledge it anyway: the server sends nothing more while two frames await an ack.
      if (id === this.connectionId) this.acknowledge(frame.number);
      return;
    }
    // Frames decode in parallel; one that finished after a newer frame was drawn is stale.
    if (id !== this.connectionId || frame.number <= this.lastDrawnFrame) {
      for (const bitmap of bitmaps) bitmap.close();
      return;
    }
    this.drawFrame(frame, bitmaps);
    this.acknowledge(frame.number);
    this.measureLatency(frame.ackSeq);
    this.dispatchEvent(new CustomEvent('frame', { detail: frame.number }));
  }

  drawFrame(frame, bitmaps) {
    if (this.canvas.width !== frame.width || this.canvas.height !== frame.height) {
      this.canvas.width = frame.width;
      this.canvas.height = frame.height;
    }
    frame.strips.forEach((strip, i) => {
      this.context2d.drawImage(bitmaps[i], 0, strip.y);
      bitmaps[i].close();
    });
    this.lastDrawnFrame = frame.number;
    this.framesDrawnCount++;
    this.drawTimes.add(1);
  }

  // Acks only ever go up, so an older frame never looks unacknowledged again to the server.
  acknowledge(frameNumber) {
    if (frameNumber <= this.lastAckedFrame) return;
    this.lastAckedFrame = frameNumber;
    this.send({ t: 'ack', frame: frameNumber });
  }

  // Every seq up to the frame's ack field has now been seen on screen.
  measureLatency(ackSeq) {
    if (!ackSeq) return;
    const now = performance.now();
    for (const [seq, sentAt] of this.seqSendTimes) {
      if (seq > ackSeq) continue;
      const sample = now - sentAt;
      this.latency = this.latency === null
        ? sample
        : this.latency + LATENCY_SMOOTHING * (sample - this.latency);
      this.seqSendTimes.delete(seq);
    }
  }

  // ---- overlay ----

  updateOverlayVisibility() {
    this.overlayBox.hidden = !this.hasAttribute('overlay');
    this.renderOverlay();
  }

  renderOverlay() {
    if (this.overlayBox.hidden || !this.latestStats) return;
    const s = this.latestStats;
    const parts = [
      `${formatNumber(s.renderMs, 1)} ms`,
      `${formatNumber(s.clientFps, 1)} fps`,
      `${formatNumber(s.mbits, 2)} Mbit/s`,
      `lat ${s.latencyMs === null ? '–' : formatNumber(s.latencyMs, 0) + ' ms'}`,
      `${s.spp ?? '–'} spp`,
    ];
    const message = s.message ? `\n${s.message}` : '';
    this.overlayBox.textContent = parts.join(' · ') + message;
  }

  // ---- input ----

  bindHandlers() {
    for (const name of ['onKeyDown', 'onKeyUp', 'onBlur', 'onVisibilityChange', 'onMouseDown',
      'onMouseMove', 'onMouseUp', 'onWheel', 'onContextMenu', 'onPointerLockChange']) {
      this[name] = this[name].bind(this);
    }
  }

  addListeners() {
    window.addEventListener('keydown', this.onKeyDown);
    window.addEventListener('keyup', this.onKeyUp);
    window.addEventListener('blur', this.onBlur);
    this.addEventListener('blur', this.onBlur);
    document.addEventListener('visibilitychange', this.onVisibilityChange);
    document.addEventListener('pointerlockchange', this.onPointerLockChange);
    this.addEventListener('mousedown', this.onMouseDown);
    window.addEventListener('mousemove', this.onMouseMove);
    window.addEventListener('mouseup', this.onMouseUp);
    this.addEventListener('wheel', this.onWheel, { passive: false });
    this.addEventListener('contextmenu', this.onContextMenu);
  }

  removeListeners() {
    window.removeEventListener('keydown', this.onKeyDown);
    window.removeEventListener('keyup', this.onKeyUp);
    window.removeEventListener('blur', this.onBlur);
    this.removeEventListener('blur', this.onBlur);
    document.removeEventListener('visibilitychange', this.onVisibilityChange);
    document.removeEventListener('pointerlockchange', this.onPointerLockChange);
    this.removeEventListener('mousedown', this.onMouseDown);
    window.removeEventListener('mousemove', this.onMouseMove);
    window.removeEventListener('mouseup', this.onMouseUp);
    this.removeEventListener('wheel', this.onWheel);
    this.removeEventListener('contextmenu', this.onContextMenu);
  }

  get pointerLocked() {
    return document.pointerLockElement === this;
  }

  // Keys are controls only while the element has the focus or holds the pointer; browser
  // shortcuts (anything with Ctrl, Alt or Meta) are left to the browser.
  ownsKeyboard(event) {
    if (!this.pointerLocked && document.activeElement !== this) return false;
    if (event.ctrlKey || event.altKey || event.metaKey) return false;
    return !BROWSER_KEYS.has(event.code) && event.code !== '';
  }

  onKeyDown(event) {
    if (!this.ownsKeyboard(event)) return;
    event.preventDefault();
    if (event.repeat || this.heldKeys.has(event.code)) return;
    if (this.sendInput({ t: 'key', code: event.code, down: true })) this.heldKeys.add(event.code);
  }

  onKeyUp(event) {
    if (!this.heldKeys.has(event.code)) return;
    event.preventDefault();
    this.heldKeys.delete(event.code);
    this.sendInput({ t: 'key', code: event.code, down: false });
  }

  // Keys released while the page cannot see them would otherwise stay held on the server.
  releaseAllKeys() {
    for (const code of this.heldKeys) this.sendInput({ t: 'key', code, down: false });
    this.heldKeys.clear();
  }

  onBlur() {
    if (!this.pointerLocked) this.releaseAllKeys();
  }

  onVisibilityChange() {
    if (document.visibilityState === 'hidden') this.releaseAllKeys();
  }

  onPointerLockChange() {
    if (!this.pointerLocked && document.activeElement !== this) this.releaseAllKeys();
  }

  // The point of the picture under the mouse, 0..1 from its top left, allowing for the bars
  // object-fit: contain leaves around it. Null when the point lies outside the picture.
  picturePoint(event, clampToPicture = false) {
    const box = this.canvas.getBoundingClientRect();
    const scale = Math.min(box.width / this.canvas.width, box.height / this.canvas.height);
    const shownWidth = this.canvas.width * scale;
    const shownHeight = this.canvas.height * scale;
    const left = box.left + (box.width - shownWidth) / 2;
    const top = box.top + (box.height - shownHeight) / 2;
    let x = (event.clientX - left) / shownWidth;
    let y = (event.clientY - top) / shownHeight;
    const inside = x >= 0 && x <= 1 && y >= 0 && y <= 1;
    if (!inside && !clampToPicture) return null;
    x = Math.min(1, Math.max(0, x));
    y = Math.min(1, Math.max(0, y));
    return { x, y };
  }

  onMouseDown(event) {
    this.focus({ preventScroll: true });
    if (event.button === 2) {
      this.rightDrag = true;
      event.preventDefault();
      return;
    }
    if (event.button !== 0) return;
    event.preventDefault(); // no text selection or native drag
    if (this.walking) {
      if (!this.pointerLocked) this.requestLock();
      return;
    }
    const point = this.picturePoint(event);
    if (!point) return;
    this.leftPress = { startX: event.clientX, startY: event.clientY, moved: false };
    this.sendInput({ t: 'grab', x: point.x, y: point.y, turn: event.shiftKey });
  }

  requestLock() {
    try {
      const result = this.requestPointerLock();
      if (result && result.catch) result.catch(() => {}); // refused (e.g. too soon after Escape)
    } catch {
      // Older browsers throw instead; the user can click again.
    }
  }

  onMouseMove(event) {
    if (this.pointerLocked || this.rightDrag) {
      this.pending.lookX += event.movementX;
      this.pending.lookY += event.movementY;
      this.scheduleFlush();
      return;
    }
    if (!this.leftPress) return;
    const press = this.leftPress;
    if (!press.moved && Math.hypot(event.clientX - press.startX, event.clientY - press.startY) > CLICK_SLOP_PX) {
      press.moved = true;
    }
    if (press.moved) {
      this.pending.drag = this.picturePoint(event, true);
      this.scheduleFlush();
    }
  }

  onMouseUp(event) {
    if (event.button === 2) {
      this.rightDrag = false;
      return;
    }
    if (event.button !== 0 || !this.leftPress) return;
    const press = this.leftPress;
    this.leftPress = null;
    this.flushPending(); // the last drag goes before the release
    this.sendInput({ t: 'release' });
    if (!press.moved) {
      const point = this.picturePoint(event, true);
      this.sendInput({ t: 'click', x: point.x, y: point.y });
    }
  }

  onWheel(event) {
    event.preventDefault();
    // A notch is about 100 pixels in Chromium and 3 lines in Firefox; trackpads send fractions,
    // which add up until they make a whole notch.
    const perNotch = event.deltaMode === WheelEvent.DOM_DELTA_LINE ? 3
      : event.deltaMode === WheelEvent.DOM_DELTA_PAGE ? 1 : 100;
    this.wheelRemainder += -event.deltaY / perNotch; // scrolling up (negative deltaY) is faster
    const notches = Math.trunc(this.wheelRemainder);
    if (notches === 0) return;
    this.wheelRemainder -= notches;
    this.pending.wheel += notches;
    this.scheduleFlush();
  }

  onContextMenu(event) {
    event.preventDefault(); // the right button looks around
  }

  // Pointer motion is summed and sent at most once per animation frame.
  scheduleFlush() {
    if (this.flushScheduled) return;
    this.flushScheduled = true;
    requestAnimationFrame(() => this.flushPending());
  }

  flushPending() {
    this.flushScheduled = false;
    const pending = this.pending;
    if (pending.lookX || pending.lookY) {
      this.sendInput({ t: 'look', dx: pending.lookX, dy: pending.lookY });
      pending.lookX = pending.lookY = 0;
    }
    if (pending.drag) {
      this.sendInput({ t: 'drag', x: pending.drag.x, y: pending.drag.y });
      pending.drag = null;
    }
    if (pending.wheel) {
      this.sendInput({ t: 'wheel', dy: pending.wheel });
      pending.wheel = 0;
    }
  }
}

function formatNumber(value, digits) {
  return typeof value === 'number' && Number.isFinite(value) ? value.toFixed(digits) : '–';
}

if (!customElements.get('penumbra-view')) customElements.define('penumbra-view', PenumbraView);
