'use strict';
// FooBall's Node.js host: runs one engine adapter (adapters/<engine>.js) for one C++ backend
// (backends/node_host/), which starts it as `node host.js` and speaks the binary protocol below
// over its stdin and stdout. Everything a person should read goes to stderr, which the C++ side
// keeps and quotes when something goes wrong.
//
// Frames, both ways: u32 payload bytes, u32 kind, payload; little-endian; every f64 at an offset
// that is a multiple of 8 from the frame's start. Strings are u32 bytes + UTF-8, padded to 8.
//   HELLO    (1)  u32 protocol, u32 0, string engine             → READY
//   OPTIONS  (2)  u32 count, u32 0, count × (string name, f64 value) → STATE
//   LOAD     (3)  f64 width, height, world, u32 balls, u32 0, balls × ball → STATE
//   WORLD    (4)  world                                          → STATE
//   SET_BALL (5)  u32 index, u32 0, ball                          → STATE
//   STEP     (6)  f64 dt, u32 forces (0 or balls), u32 0, forces × (f64 fx, fy) → STATE
//   world: f64 gx, gy, air resistance, u32 flags (1 left, 2 right, 4 bottom, 8 top, 16 ball
//          collisions), u32 0;  ball: f64 x, y, vx, vy, radius, mass
//   READY    (100) u32 protocol, u32 0, string node version, string engine version
//   STATE    (101) u32 balls, u32 0, f64 ball collisions, wall collisions, wall impulse (N·s),
//                  drag loss (J), engine steps, balls brought back into the box by the adapter,
//                  s spent in the adapter's step, then balls × (f64 x, y, vx, vy)
//   ERROR    (199) string message
// SI units, y up, as FooBall's scene; each adapter converts to its engine's.

const fs = require('fs');
const path = require('path');
const util = require('util');

const PROTOCOL = 1;
const KIND = {HELLO: 1, OPTIONS: 2, LOAD: 3, WORLD: 4, SET_BALL: 5, STEP: 6,
              READY: 100, STATE: 101, ERROR: 199};
const ENGINES = new Set(['matter', 'rapier', 'box2d3']);

// Engines print (matter's warnOnce, wasm loaders): stdout is the protocol's, so everything
// they say goes to stderr, written at once (Node writes to a pipe asynchronously, and what is
// still queued when the host is killed or exits would be lost to the C++ side's error).
function say(...args) { fs.writeSync(2, util.format(...args) + '\n'); }
console.log = console.info = console.debug = console.warn = console.error = say;

function readFully(buffer, length) {
  let done = 0;
  while (done < length) {
    let n;
    try {
      n = fs.readSync(0, buffer, done, length - done, null);
    } catch (error) {
      if (error.code === 'EAGAIN') continue;
      throw error;
    }
    if (n === 0) return false;  // the C++ side closed the pipe: we are done
    done += n;
  }
  return true;
}

function writeFully(buffer, length) {
  let done = 0;
  while (done < length) {
    try {
      done += fs.writeSync(1, buffer, done, length - done);
    } catch (error) {
      if (error.code !== 'EAGAIN') throw error;
    }
  }
}

/// A growable byte buffer whose start is 8-aligned, with views for the frame readers.
class Frame {
  constructor(bytes) { this.resize(bytes); }
  resize(bytes) {
    this.buffer = new ArrayBuffer(bytes);
    this.bytes = new Uint8Array(this.buffer);
    this.view = new DataView(this.buffer);
  }
  ensure(bytes) {
    if (this.buffer.byteLength < bytes) this.resize(Math.max(bytes, 2 * this.buffer.byteLength));
  }
  f64s(offset, count) { return new Float64Array(this.buffer, offset, count); }
}

const input = new Frame(1 << 16);
const output = new Frame(1 << 16);

function readString(state) {
  const length = input.view.getUint32(state.offset, true);
  const text = Buffer.from(input.buffer, state.offset + 4, length).toString('utf8');
  state.offset += (4 + length + 7) & ~7;
  return text;
}

function writeString(offset, text) {
  const encoded = Buffer.from(text, 'utf8');
  output.ensure(offset + 8 + encoded.length + 8);
  output.view.setUint32(offset, encoded.length, true);
  output.bytes.set(encoded, offset + 4);
  return offset + ((4 + encoded.length + 7) & ~7);
}

function send(kind, payloadBytes) {
  output.view.setUint32(0, payloadBytes, true);
  output.view.setUint32(4, kind, true);
  writeFully(output.bytes, 8 + payloadBytes);
}

function sendError(message) {
  const end = writeString(8, message);
  send(KIND.ERROR, end - 8);
}

function readWorld(offset) {
  const v = input.view;
  const flags = v.getUint32(offset + 24, true);
  return {
    gravity: [v.getFloat64(offset, true), v.getFloat64(offset + 8, true)],
    airResistance: v.getFloat64(offset + 16, true),  // 1/s
    walls: {left: !!(flags & 1), right: !!(flags & 2), bottom: !!(flags & 4), top: !!(flags & 8)},
    ballCollisions: !!(flags & 16),
  };
}
const WORLD_BYTES = 32;
const BALL_DOUBLES = 6;

/// What every adapter counts, cumulative since LOAD (an OPTIONS rebuild keeps them).
function zeroCounters() {
  return {ballCollisions: 0, wallCollisions: 0, wallImpulse: 0, dragLoss: 0, engineSteps: 0,
          ballsBroughtBack: 0, stepSeconds: 0};
}

async function main() {
  if (!readFully(input.bytes, 8)) return;
  const helloBytes = input.view.getUint32(0, true);
  if (input.view.getUint32(4, true) !== KIND.HELLO) throw new Error('expected HELLO first');
  input.ensure(helloBytes);
  if (!readFully(input.bytes, helloBytes)) return;
  const protocol = input.view.getUint32(0, true);
  const engineName = readString({offset: 8});
  if (protocol !== PROTOCOL) {
    sendError(`protocol ${protocol} asked, host speaks ${PROTOCOL}`);
    return;
  }
  if (!ENGINES.has(engineName)) {
    sendError(`no adapter for engine '${engineName}'`);
    return;
  }
  const adapter = require(path.join(__dirname, 'adapters', engineName + '.js'));
  const engine = await adapter.create();

  output.view.setUint32(8, PROTOCOL, true);
  output.view.setUint32(12, 0, true);
  let end = writeString(16, process.versions.node);
  end = writeString(end, engine.version);
  send(KIND.READY, end - 8);

  let options = {};
  let scene = null;  // {width, height, world, balls: Float64Array(6 n)} as last loaded
  let counters = zeroCounters();
  let state = new Float64Array(0);  // 4 n: x, y, vx, vy

  function reply() {
    const n = scene ? scene.balls.length / BALL_DOUBLES : 0;
    const bytes = 8 + 7 * 8 + 4 * 8 * n;
    output.ensure(8 + bytes);
    output.view.setUint32(8, n, true);
    output.view.setUint32(12, 0, true);
    const numbers = output.f64s(16, 7 + 4 * n);
    numbers[0] = counters.ballCollisions;
    numbers[1] = counters.wallCollisions;
    numbers[2] = counters.wallImpulse;
    numbers[3] = counters.dragLoss;
    numbers[4] = counters.engineSteps;
    numbers[5] = counters.ballsBroughtBack;
    numbers[6] = counters.stepSeconds;
    if (n > 0) {
      if (state.length !== 4 * n) state = new Float64Array(4 * n);
      engine.readState(state);
      numbers.set(state, 7);
    }
    send(KIND.STATE, bytes);
  }

  // An adapter may have a `prepare(options)` that loads what the options ask for (a WebAssembly
  // module, which loads asynchronously) before a `load` that uses them.

  /// The scene as the engine has it now, for a rebuild with new options.
  function currentScene() {
    const balls = Float64Array.from(scene.balls);
    const n = balls.length / BALL_DOUBLES;
    if (state.length !== 4 * n) state = new Float64Array(4 * n);
    engine.readState(state);
    for (let i = 0; i < n; ++i) {
      for (let k = 0; k < 4; ++k) balls[BALL_DOUBLES * i + k] = state[4 * i + k];
    }
    return {...scene, balls};
  }

  for (;;) {
    if (!readFully(input.bytes, 8)) return;
    const bytes = input.view.getUint32(0, true);
    const kind = input.view.getUint32(4, true);
    input.ensure(bytes);
    if (!readFully(input.bytes, bytes)) return;
    try {
      switch (kind) {
        case KIND.OPTIONS: {
          const count = input.view.getUint32(0, true);
          const at = {offset: 8};
          options = {};
          for (let i = 0; i < count; ++i) {
            const name = readString(at);
            options[name] = input.view.getFloat64(at.offset, true);
            at.offset += 8;
          }
          if (engine.prepare) await engine.prepare(options);
          if (scene) {
            scene = currentScene();
            engine.load(scene, options, counters);
          }
          break;
        }
        case KIND.LOAD: {
          const v = input.view;
          const n = v.getUint32(16 + WORLD_BYTES, true);
          scene = {
            width: v.getFloat64(0, true),
            height: v.getFloat64(8, true),
            world: readWorld(16),
            balls: Float64Array.from(input.f64s(16 + WORLD_BYTES + 8, BALL_DOUBLES * n)),
          };
          counters = zeroCounters();
          engine.load(scene, options, counters);
          break;
        }
        case KIND.WORLD:
          scene.world = readWorld(0);
          engine.setWorld(scene.world);
          break;
        case KIND.SET_BALL: {
          const index = input.view.getUint32(0, true);
          const ball = Float64Array.from(input.f64s(8, BALL_DOUBLES));
          scene.balls.set(ball, BALL_DOUBLES * index);
          engine.setBall(index, ball);
          break;
        }
        case KIND.STEP: {
          const dt = input.view.getFloat64(0, true);
          const forceCount = input.view.getUint32(8, true);
          const start = process.hrtime.bigint();
          engine.step(dt, forceCount > 0 ? input.f64s(16, 2 * forceCount) : null, counters);
          counters.stepSeconds += Number(process.hrtime.bigint() - start) * 1e-9;
          break;
        }
        default:
          throw new Error(`unknown frame kind ${kind}`);
      }
    } catch (error) {
      console.error(error && error.stack ? error.stack : String(error));
      sendError(String(error && error.message ? error.message : error));
      continue;
    }
    reply();
  }
}

main().catch((error) => {
  console.error(error && error.stack ? error.stack : String(error));
  process.exit(1);
});
