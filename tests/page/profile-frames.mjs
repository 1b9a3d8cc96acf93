// Where the page's main thread spends its frames while the Murex grows: a Chromium trace
// (timeline events with thread clocks, the V8 sampling profiler at 100 µs) of the page with
// WORKERS workers (1 unless set) on BACKEND (`WebGL2` unless set, or `WebGPU`) for SECONDS
// seconds (40 unless set) of growth, each requestAnimationFrame callback's thread time split
// among the functions its samples stood in (wasm functions by name: build with names kept),
// and the other tasks the thread ran between
// frames (the workers' replies decoded in their message events, GC). A build that marks its
// frames with `console.timeStamp` (`#phase` between phases, `>name` and `<name` around a call
// into the page) has each frame's thread time split by those marks too. Prints tables; asserts
// nothing. `node tests/page/profile-frames.mjs WWW [TRACE.json]` records (and keeps the trace);
// `node tests/page/profile-frames.mjs TRACE.json` reads a trace kept before.
import { readFile, writeFile } from 'node:fs/promises';
import { launch, pageThread, trace, waitForState } from './browser.mjs';
import { serve } from './serve.mjs';

const workers = Number(process.env.WORKERS ?? 1);
const seconds = Number(process.env.SECONDS ?? 40);
const backend = process.env.BACKEND ?? 'WebGL2';

const CATEGORIES = [
  'toplevel', 'devtools.timeline', 'disabled-by-default-devtools.timeline', 'v8', 'v8.execute',
  'disabled-by-default-v8.gc', 'disabled-by-default-v8.cpu_profiler',
  'disabled-by-default-v8.cpu_profiler.hires', 'blink', 'gpu',
];

/** Records a trace of the page served from `root` while the Murex grows. */
async function record(root, out) {
  const server = await serve(root);
  const browser = await launch(backend);
  let events;
  try {
    const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
    await page.goto(`http://127.0.0.1:${server.address().port}/?workers=${workers}#v=1&preset=murex-cabritii`);
    await waitForState(page, ['growing'], 300_000);
    let rows0;
    let state;
    events = await trace(page, CATEGORIES, async () => {
      rows0 = await page.evaluate(() => document.body.dataset.rows);
      await page.waitForTimeout(seconds * 1000);
      state = await page.evaluate(() => ({ ...document.body.dataset }));
    });
    console.log(`rows ${rows0} → ${state.rows}, state ${state.state}`);
    await page.close();
  } finally {
    await browser.close();
    server.close();
  }
  if (out) await writeFile(out, JSON.stringify(events));
  return events;
}

/** Per-frame figures of a trace: the rAF callback, the rest of its task, and what ran before the next frame. */
function analyze(events) {
  const { frames: fires, onThread: onMain } = pageThread(events);
  const { pid, tid } = fires[0];
  const within = (e, k) => e.ts >= k.ts && e.ts < k.ts + k.dur;
  const tasks = onMain.filter((e) => e.name === 'ThreadControllerImpl::RunTask' && e.tdur !== undefined);
  const marks = events.filter((e) => e.pid === pid && e.tid === tid && e.name === 'TimeStamp' && e.tts !== undefined)
    .sort((a, b) => a.ts - b.ts);

  // The main thread's samples; the Profile event names the thread, its chunks carry the nodes.
  const profile = events.find((e) => e.name === 'Profile' && e.pid === pid && e.tid === tid);
  const nodes = new Map();
  const samples = [];
  let t = profile.args.data.startTime;
  for (const chunk of events.filter((e) => e.name === 'ProfileChunk' && e.pid === pid && e.id === profile.id)) {
    const cpu = chunk.args.data.cpuProfile ?? {};
    for (const n of cpu.nodes ?? []) nodes.set(n.id, n);
    (cpu.samples ?? []).forEach((id, i) => {
      t += chunk.args.data.timeDeltas[i];
      samples.push({ t, id });
    });
  }
  samples.sort((a, b) => a.t - b.t);
  const name = (id) => {
    const f = nodes.get(id).callFrame;
    return f.functionName || `(anonymous ${f.url.split('/').pop()}:${f.lineNumber})`;
  };
  /** A sample's leaf, and the first of our own wasm functions under it (its caller in the crate). */
  const attribute = (id) => {
    const leaf = name(id);
    let ours = '';
    for (let n = nodes.get(id); n; n = nodes.get(n.parent)) {
      if (/seashells_core|^seashells::/.test(n.callFrame.functionName)) {
        ours = n.callFrame.functionName.replace(/::h[0-9a-f]{16}$/, '');
        break;
      }
    }
    return { leaf: leaf.replace(/::h[0-9a-f]{16}$/, ''), ours };
  };
  /**
   * The samples in [start, end) by leaf and by our caller, each weighing `thread / count`: the
   * sampler's signals reach the thread only while it runs, so counts follow thread time.
   */
  const sampled = (start, end, thread) => {
    const leaves = new Map();
    const ours = new Map();
    const inside = samples.filter((s) => s.t >= start && s.t < end);
    for (const s of inside) {
      const a = attribute(s.id);
      const w = thread / inside.length;
      leaves.set(a.leaf, (leaves.get(a.leaf) ?? 0) + w);
      ours.set(a.ours || '(none of ours)', (ours.get(a.ours || '(none of ours)') ?? 0) + w);
    }
    return { leaves, ours, count: inside.length };
  };

  const kind = (k) => {
    const inner = onMain.filter((e) => e !== k && within(e, k)).slice(0, 3).map((e) => e.name);
    if (inner.includes('HandlePostMessage')) return 'worker reply (message event: copy and decode)';
    if (inner.some((n) => /GC/.test(n))) return 'GC (incremental marking, sweeping)';
    if (inner.length === 0) return 'empty';
    return 'other';
  };
  const frames = [];
  for (let i = 0; i + 1 < fires.length; i += 1) {
    const f = fires[i];
    const task = tasks.find((k) => within(f, k));
    const next = tasks.find((k) => within(fires[i + 1], k));
    if (!task || !next) continue;
    const lifecycle = onMain.filter((e) => e.name === 'WebFrameWidgetImpl::UpdateLifecycle' && within(e, task));
    const gc = onMain.filter((e) => within(e, f) && /^(MinorGC|MajorGC|V8\.GCScavenger|V8\.GCIncrementalMarking|V8\.GCFinalizeMC)$/.test(e.name));
    const before = new Map();
    for (const k of tasks.filter((x) => x.ts >= task.ts + task.dur && x.ts < next.ts)) {
      before.set(kind(k), (before.get(kind(k)) ?? 0) + k.tdur / 1000);
    }
    // Thread time between the marks of a build that has them (phases of `App::frame`, and
    // each call into the browser timed by a wrapper: `>name` … `<name`).
    const stamps = onMain.length ? marks.filter((m) => m.ts >= f.ts && m.ts < f.ts + f.dur) : [];
    const phases = new Map();
    const calls = new Map();
    let phase = '(before #start)';
    let phaseStart = f.tts;
    const open = [];
    for (const m of stamps) {
      const text = m.args.data.message;
      if (text.startsWith('#')) {
        phases.set(phase, (phases.get(phase) ?? 0) + (m.tts - phaseStart) / 1000);
        phase = text;
        phaseStart = m.tts;
      } else if (text.startsWith('>')) {
        open.push(m);
      } else if (open.length > 0) {
        const o = open.pop();
        if (open.length === 0) {
          const d = (m.tts - o.tts) / 1000;
          const key = text.slice(1);
          calls.set(key, (calls.get(key) ?? 0) + d);
          const inPhase = `${phase} calls into the browser`;
          phases.set(inPhase, (phases.get(inPhase) ?? 0) + d);
        }
      }
    }
    if (stamps.length > 0) phases.set(phase, (phases.get(phase) ?? 0) + (f.tts + f.tdur - phaseStart) / 1000);
    // A reply taken in: a message event since the previous frame's task.
    const prev = frames.at(-1);
    frames.push({
      thread: f.tdur / 1000,
      wall: f.dur / 1000,
      task: task.tdur / 1000,
      lifecycle: lifecycle.reduce((s, e) => s + e.tdur, 0) / 1000,
      gc: gc.reduce((s, e) => s + e.tdur, 0) / 1000,
      before,
      reply: prev ? (prev.before.get('worker reply (message event: copy and decode)') ?? 0) > 0 : false,
      interval: (fires[i + 1].ts - f.ts) / 1000,
      phases,
      calls,
      stamps: stamps.length,
      ...sampled(f.ts, f.ts + f.dur, f.tdur / 1000),
    });
  }
  return frames;
}

const pct = (xs, p) => xs[Math.min(xs.length - 1, Math.floor((p / 100) * xs.length))];
const sum = (maps) => {
  const total = new Map();
  for (const m of maps) for (const [k, v] of m) total.set(k, (total.get(k) ?? 0) + v);
  return total;
};
const top = (m, n, count) => [...m].sort((a, b) => b[1] - a[1]).slice(0, n)
  .map(([k, v]) => `    ${(v / count).toFixed(2).padStart(6)} ms  ${k.slice(0, 110)}`).join('\n');

function group(label, xs) {
  const mean = (k) => (xs.reduce((s, x) => s + x[k], 0) / xs.length).toFixed(2);
  console.log(`\n== ${label}: ${xs.length} frames (${xs.filter((x) => x.reply).length} took in a reply), rAF thread ${xs.map((x) => x.thread.toFixed(1)).slice(-10).join(' ')}`);
  console.log(`  mean per frame: rAF callback ${mean('thread')} ms thread (${mean('wall')} wall), of it GC ${mean('gc')}; `
    + `its whole task ${mean('task')} ms, of it style/layout/paint/commit ${mean('lifecycle')}; next frame after ${mean('interval')} ms`);
  console.log('  rAF callback by leaf (browser call or wasm function), thread ms per frame:');
  console.log(top(sum(xs.map((x) => x.leaves)), 14, xs.length));
  console.log('  rAF callback by our caller (first seashells function up the stack):');
  console.log(top(sum(xs.map((x) => x.ours)), 10, xs.length));
  if (xs.some((x) => x.stamps > 0)) {
    console.log(`  marked phases (thread ms per frame; "calls into the browser" is the part of a phase in imports; ${mean('stamps')} marks a frame):`);
    console.log(top(sum(xs.map((x) => x.phases)), 20, xs.length));
    console.log('  calls into the browser by import (thread ms per frame):');
    console.log(top(sum(xs.map((x) => x.calls)), 14, xs.length));
  }
  console.log('  tasks between this frame and the next, thread ms per frame:');
  console.log(top(sum(xs.map((x) => x.before)), 5, xs.length));
}

const events = process.argv[2].endsWith('.json')
  ? JSON.parse(await readFile(process.argv[2], 'utf8'))
  : await record(process.argv[2], process.argv[3]);
const frames = analyze(events).slice(2);
const sorted = [...frames].sort((a, b) => a.thread - b.thread);
console.log(`${frames.length} frames: rAF thread p50 ${pct(sorted, 50).thread.toFixed(2)}, p99 ${pct(sorted, 99).thread.toFixed(2)} ms; `
  + `whole task p50 ${pct(frames.map((x) => x.task).sort((a, b) => a - b), 50).toFixed(2)}, p99 ${pct(frames.map((x) => x.task).sort((a, b) => a - b), 99).toFixed(2)} ms`);
const one = Math.max(1, Math.ceil(frames.length / 100));
group('slowest 1 %', sorted.slice(-one));
group('slowest 5 %', sorted.slice(-Math.ceil(frames.length / 20)));
const mid = Math.floor(sorted.length / 2);
const band = Math.max(1, Math.ceil(frames.length / 20));
group('median ±5 %', sorted.slice(mid - band, mid + band));
group('frames that took in a reply', frames.filter((x) => x.reply));
group('frames that did not', frames.filter((x) => !x.reply));
