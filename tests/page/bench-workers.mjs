// Benchmarks of growth off the page's thread (issue 30), each beside its baseline in the same
// run: what one core does (the pattern solvers' rates, one preset per model, and the Murex
// polygonized whole at 128³) on a worker's thread and on the page's; the page's own script
// time per frame while the Murex grows (50th and 99th percentiles over at least 200 frames
// of growth, each frame's wall time and its thread's processor time from a trace), with the
// view drawn in the drawing worker and, as before it, on the page's thread (`view=page`; with
// `workers=0` too, how the page worked before workers); the
// Murex finished at 256³ with 1 and W workers; and every gallery picture on the page's thread
// and with 1 and W workers; the turbinate's map of 64 shells with 1 and W workers. W is the pool this
// machine gets (`navigator.hardwareConcurrency − 1`, at least 1) and 2 besides, so that the
// sharing shows even on a 2-core machine. Prints figures; asserts nothing.
//
// `node tests/page/bench-workers.mjs map` times the map of shells alone, with 1 and 2 workers.
// `node tests/page/bench-workers.mjs gallery [BASELINE_WWW]` times the gallery alone, on the
// page's thread, with 1 worker and with the default pool, beside the same on another build's
// www (say main's) served alongside, alternately in the same run.
// `node tests/page/bench-workers.mjs frames [DIR …]` gives only the frame figures, for each
// directory holding a built page (`www` unless given; say, another commit's `www` beside
// this one's), served side by side and measured in turns (ROUNDS, 2 unless set, of FRAMES
// frames, 100 unless set, each, with WORKERS workers, `1` unless set, and the view drawn in
// each of VIEWS, `worker,page` unless set: in the drawing worker, on the page's thread) in one browser on
// BACKEND (`WebGL2` unless set, or `WebGPU`), each round beside a plain script's frames
// (`floor/index.html`: a reply taken into a GPU buffer, a request posted, the progress moved,
// 318,402 triangles drawn with raw WebGL2), the least a page that draws on its own thread
// spends. `make bench` sets the same baseline beside the page's WebGL2 frames.
import { launch, open, pageThread, session, trace, waitForState } from './browser.mjs';
import { serve } from './serve.mjs';

/**
 * The page's frames measured by `make bench`: as the page worked before workers, the view drawn
 * on the page's thread beside one worker (before the drawing worker), and drawn in the drawing
 * worker with one worker in its pool (the page as it is).
 */
const FRAME_RUNS = [
  ['workers=0&view=page', "drawn and grown on the page's thread"],
  ['workers=1&view=page', "drawn on the page's thread, one worker"],
  ['workers=1', 'drawn in the drawing worker, one worker'],
];

/** Wraps requestAnimationFrame before the page loads, to time each frame's callback while the shell grows. */
function timeFrames() {
  window.__frameMs = [];
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => raf((t) => {
    const growing = document.body.dataset.state === 'growing';
    const start = performance.now();
    try {
      callback(t);
    } finally {
      if (growing) window.__frameMs.push(performance.now() - start);
    }
  });
}

const percentile = (xs, p) => {
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))];
};

/** Trace events of the page's thread that run script: a frame's callback, an event handler (a worker's reply), a timer, a microtask checkpoint. */
const SCRIPT_TASKS = new Set(['FireAnimationFrame', 'EventDispatch', 'FunctionCall', 'TimerFire', 'FireIdleCallback', 'RunMicrotasks']);

/**
 * The page's main-thread frames while the Murex grows, from a trace of `page`: each
 * `requestAnimationFrame` callback's wall time and the time its thread was on a processor
 * (the trace's thread clock), in milliseconds, and `script`: that thread time plus the thread
 * time of every other script task the page's thread ran since the frame before (the workers'
 * replies read in their `message` events, timers, microtasks), so that no script the page
 * runs per frame is left out. Wall time also counts the waits when the processor went to
 * another process (on two cores: the worker, the GPU process's software rendering, other
 * programs) and any wait for the GPU process; thread time is the script's own.
 */
async function traceFrames(page, during) {
  return framesOf(await trace(page, ['devtools.timeline'], during));
}

/** The frames of trace `events` as `traceFrames` gives them. */
function framesOf(events) {
  // The thread's outermost script tasks, in time order (a FunctionCall inside an EventDispatch
  // is counted once, with it).
  const tasks = pageThread(events).onThread.filter((e) => e.tdur !== undefined && SCRIPT_TASKS.has(e.name));
  const outermost = [];
  for (const e of tasks) {
    const last = outermost[outermost.length - 1];
    if (!last || e.ts >= last.ts + last.dur) outermost.push(e);
  }
  const result = [];
  let between = 0;
  for (const e of outermost) {
    if (e.name === 'FireAnimationFrame') {
      result.push({ wall: e.dur / 1000, thread: e.tdur / 1000, script: (e.tdur + between) / 1000 });
      between = 0;
    } else {
      between += e.tdur;
    }
  }
  return result;
}

/**
 * Script milliseconds per frame (p50, p99) while the Murex grows, served from `base`: at least
 * `least` frames timed while `data-state` says growing (the shell is opened again if it is
 * grown before), at most `seconds` of growth in all. `wall` is each callback's wall time as a
 * wrapper in the page times it; `thread` is its thread's processor time from a trace, and
 * `script` that with the thread's other script tasks since the frame before (see `traceFrames`).
 */
async function frameScript(browser, base, query, least = 200, seconds = 600) {
  const ms = [];
  const thread = [];
  const script = [];
  let rows = 0;
  const started = Date.now();
  while (ms.length < least && Date.now() - started < seconds * 1000) {
    const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
    await page.addInitScript(timeFrames);
    await page.goto(`${base}?${query}#v=1&preset=murex-cabritii`);
    await waitForState(page, ['growing'], 300_000);
    const traced = await traceFrames(page, async () => {
      await page.evaluate(() => { window.__frameMs = []; });
      await page.waitForFunction((n) => document.body.dataset.state !== 'growing' || window.__frameMs.length >= n,
        least - ms.length, { timeout: seconds * 1000, polling: 500 }).catch(() => {});
    });
    const timed = await page.evaluate(() => window.__frameMs);
    ms.push(...timed);
    // The trace's last frames, as many as the wrapper timed while the shell grew.
    const last = traced.slice(-timed.length);
    thread.push(...last.map((f) => f.thread));
    script.push(...last.map((f) => f.script));
    rows += Number(await page.evaluate(() => document.body.dataset.rows));
    await page.close();
  }
  return {
    wall: ms,
    thread,
    script,
    frames: ms.length,
    p50: percentile(ms, 50),
    p99: percentile(ms, 99),
    thread50: percentile(thread, 50),
    thread99: percentile(thread, 99),
    script50: percentile(script, 50),
    script99: percentile(script, 99),
    rows,
    seconds: (Date.now() - started) / 1000,
  };
}

const frameLine = (f) => `p50 ${f.p50.toFixed(2)} ms, p99 ${f.p99.toFixed(2)} ms wall; `
  + `p50 ${f.thread50.toFixed(2)} ms, p99 ${f.thread99.toFixed(2)} ms on the thread; `
  + `p50 ${f.script50.toFixed(2)} ms, p99 ${f.script99.toFixed(2)} ms of all the thread's script, over ${f.frames} frames `
  + `(${f.rows} rows grown in ${f.seconds.toFixed(0)} s)`;

/**
 * The baseline of the frame figures: a plain script's frames (`floor/index.html`: a reply
 * taken into a GPU buffer, a request posted, the progress moved, 318,402 triangles drawn
 * with raw WebGL2), the least a page that draws on its own thread spends, measured as the
 * page's are.
 */
async function plainScript(browser, least) {
  const server = await serve(new URL('floor/', import.meta.url).pathname);
  try {
    return await frameScript(browser, `http://127.0.0.1:${server.address().port}/`, 'workers=1', least);
  } finally {
    server.close();
  }
}

const PLAIN = "a plain script drawing on the page's thread (raw WebGL2)";

/** The benchmark's figures of one core (pattern rates, the Murex polygonized) on the page's thread and on a worker. */
async function oneCore(browser, base) {
  const page = await browser.newPage();
  await page.goto(`${base}bench.html`);
  const parse = (text) => new Map(text.trim().split('\n').map((line) => {
    const m = line.match(/^(.*?)\s{2,}([\d.]+) (\S.*?)(?:\s+\(spread ([\d.]+) %\))?$/);
    return [m[1], { value: Number(m[2]), unit: m[3], spread: m[4] }];
  }));
  const [thread, worker] = await page.evaluate(async () => {
    const module = await import(new URL('pkg/seashells.js', document.baseURI).href);
    await module.default();
    const onThread = module.benchmark_one_core();
    const onWorker = await new Promise((resolve, reject) => {
      const w = new Worker(new URL('bench-worker.js', document.baseURI), { type: 'module' });
      w.onmessage = (e) => { resolve(e.data); w.terminate(); };
      w.onerror = (e) => reject(new Error(e.message));
    });
    return [onThread, onWorker];
  });
  await page.close();
  return { thread: parse(thread), worker: parse(worker) };
}

/** Rows of the Murex grown per second over `seconds` at full speed with `query` (a window, not the whole growth, which takes minutes on the page's thread). */
async function murexGrowth(browser, base, query, seconds = 60) {
  const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
  await page.goto(`${base}?${query}#v=1&preset=murex-cabritii&growth.speed=200`);
  await waitForState(page, ['growing'], 300_000);
  const rows = async () => Number(await page.evaluate(() => document.body.dataset.rows));
  const first = await rows();
  await page.waitForTimeout(seconds * 1000);
  const grown = (await rows()) - first;
  await page.close();
  return grown / seconds;
}

/** Seconds from End to the Murex grown whole at 256³ (`data-growth` done). */
async function murexFinish(browser, base, workers) {
  const { page } = await open(browser, `${base}?workers=${workers}#v=1&preset=murex-cabritii&form.resolution=256&growth.speed=0.05`);
  await waitForState(page, ['growing'], 300_000);
  const seconds = await page.evaluate(() => new Promise((resolve) => {
    const start = performance.now();
    const watch = new MutationObserver(() => {
      if (document.body.dataset.growth === 'done') {
        watch.disconnect();
        resolve((performance.now() - start) / 1000);
      }
    });
    watch.observe(document.body, { attributes: true });
    document.getElementById('finish').click();
  }));
  await page.close();
  return seconds;
}

/**
 * Seconds from opening the gallery to every picture drawn and the page saying so (with
 * `workers` undefined, the default pool).
 */
async function gallery(browser, base, workers) {
  const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
  const start = Date.now();
  await page.goto(workers === undefined ? base : `${base}?workers=${workers}`);
  await page.waitForFunction(() => document.body.dataset.pictures === 'done', null, { timeout: 600_000 });
  const seconds = (Date.now() - start) / 1000;
  await page.close();
  return seconds;
}

/**
 * Seconds from pressing Map on the turbinate shell, while it grows, to its 64 shells drawn (the
 * morphospace over λᵣ and λ_z), with `workers` workers. The button is clicked from the page's
 * script: a click by the test driver first waits for the busy page's button to hold still.
 */
async function shapeMap(browser, base, workers) {
  const page = await browser.newPage({ viewport: { width: 1100, height: 1000 } });
  await page.goto(`${base}?workers=${workers}#v=1&preset=turbinate`);
  await waitForState(page, ['growing', 'grown']);
  const start = Date.now();
  await page.evaluate(() => document.getElementById('map-open').click());
  await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 600_000 });
  const seconds = (Date.now() - start) / 1000;
  await page.close();
  return seconds;
}

export async function benchWorkers() {
  const { browser, base, close } = await session('WebGL2');
  try {
    const page = await browser.newPage();
    await page.goto(base);
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    await page.close();
    const pool = Math.min(8, Math.max(1, cores - 1));
    const sizes = [...new Set([1, pool, 2])];
    console.log(`workers (Chromium ${browser.version()}, ${cores} logical processors, pool of ${pool})`);
    const one = await oneCore(browser, base);
    for (const [what, t] of one.thread) {
      const w = one.worker.get(what);
      const spread = (x) => (x.spread ? ` (spread ${x.spread} %)` : '');
      // A time (ms) is better lower, a rate higher: the worker's speed over the page's thread.
      const speed = t.unit === 'ms' ? t.value / w.value : w.value / t.value;
      console.log(`one core, ${what}: page's thread ${t.value} ${t.unit}${spread(t)}, a worker ${w.value} ${w.unit}${spread(w)} (the worker at × ${speed.toFixed(2)} the page's thread's speed)`);
    }
    for (const [query, what] of FRAME_RUNS) {
      const f = await frameScript(browser, base, query);
      console.log(`Murex growing, page script per frame, WebGL2, ${what} (${query}): ${frameLine(f)}`);
    }
    console.log(`beside it, ${PLAIN}: ${frameLine(await plainScript(browser, 200)).replace('rows grown', 'frames')}`);
    const webgpu = await launch('WebGPU');
    try {
      for (const [query, what] of FRAME_RUNS.slice(1)) {
        const f = await frameScript(webgpu, base, query);
        console.log(`Murex growing, page script per frame, WebGPU, ${what} (${query}): ${frameLine(f)}`);
      }
    } finally {
      await webgpu.close();
    }
    // The worker's growth budget per request (`grow-budget=N`): fewer round trips against a
    // change of value waiting behind the growth under way for as long.
    const page0 = await murexGrowth(browser, base, 'workers=0&view=page');
    console.log(`Murex growing at full speed on the page's thread: ${page0.toFixed(2)} rows/s`);
    for (const budget of [12, 24, 48]) {
      const rate = await murexGrowth(browser, base, `workers=1&grow-budget=${budget}`);
      console.log(`Murex growing at full speed on one worker, ${budget} ms a request: ${rate.toFixed(2)} rows/s (× ${(rate / page0).toFixed(2)} of the page's thread)`);
    }
    const finish = {};
    for (const workers of sizes) {
      finish[workers] = await murexFinish(browser, base, workers);
      console.log(`Murex finish at 256³, ${workers} worker(s): ${finish[workers].toFixed(2)} s (× ${(finish[1] / finish[workers]).toFixed(2)} of one worker)`);
    }
    const pictures = {};
    for (const workers of [0, ...sizes]) {
      pictures[workers] = await gallery(browser, base, workers);
      const ratio = workers === 0 ? '' : ` (× ${(pictures[0] / pictures[workers]).toFixed(2)} of the page's own thread)`;
      console.log(`all gallery pictures, workers=${workers}: ${pictures[workers].toFixed(2)} s${ratio}`);
    }
    const map = {};
    for (const workers of sizes) {
      map[workers] = await shapeMap(browser, base, workers);
      console.log(`the turbinate's map of 64 shells, ${workers} worker(s): ${map[workers].toFixed(2)} s (× ${(map[1] / map[workers]).toFixed(2)} of one worker)`);
    }
  } finally {
    await close();
  }
}

/** The gallery's figures of this build's www beside those of `baseline` (a www directory). */
export async function benchGallery(baseline) {
  const roots = { this: new URL('../../www/', import.meta.url).pathname };
  if (baseline) roots.baseline = baseline;
  const servers = await Promise.all(Object.values(roots).map((root) => serve(root)));
  const bases = servers.map((s) => `http://127.0.0.1:${s.address().port}/`);
  const browser = await launch('WebGL2');
  try {
    console.log(`gallery (Chromium ${browser.version()})`);
    for (const [label, workers] of [["page's thread", 0], ['1 worker', 1], ['default pool', undefined]]) {
      const figures = [];
      for (const [i, name] of Object.keys(roots).entries()) {
        figures.push(`${name} ${(await gallery(browser, bases[i], workers)).toFixed(1)} s`);
      }
      console.log(`all gallery pictures, ${label}: ${figures.join(', ')}`);
    }
  } finally {
    await browser.close();
    servers.forEach((s) => s.close());
  }
}

/**
 * Only the frame figures, for each of `roots` (directories holding a built page: `www` and,
 * say, another commit's build) served side by side and measured in turn, `rounds` times, in
 * the same browser: on a shared machine the load changes within minutes, and turns spread it
 * over every build alike.
 */
export async function benchFrames(roots, rounds = 2, least = 100, queries = ['workers=1', 'workers=1&view=page'], backend = 'WebGL2') {
  const servers = await Promise.all(roots.map((root) => serve(root)));
  const browser = await launch(backend);
  try {
    console.log(`frames (Chromium ${browser.version()}, ${backend}), ${rounds} rounds of ${least} frames`);
    const all = new Map();
    const record = (key, f) => all.set(key, [...(all.get(key) ?? []), f]);
    for (let round = 0; round < rounds; round += 1) {
      for (const [i, server] of servers.entries()) {
        for (const query of queries) {
          const f = await frameScript(browser, `http://127.0.0.1:${server.address().port}/`, query, least);
          console.log(`round ${round + 1}, ${roots[i]}, ${query}: ${frameLine(f)}`);
          record(`${roots[i]}, ${query}`, f);
        }
      }
      const f = await plainScript(browser, least);
      console.log(`round ${round + 1}, ${PLAIN}: ${frameLine(f).replace('rows grown', 'frames')}`);
      record(PLAIN, f);
    }
    for (const [key, fs] of all) {
      const wall = fs.flatMap((f) => f.wall);
      const thread = fs.flatMap((f) => f.thread);
      const script = fs.flatMap((f) => f.script);
      console.log(`${key}, the rounds' ${wall.length} frames together: p50 ${percentile(wall, 50).toFixed(2)} / `
        + `p99 ${percentile(wall, 99).toFixed(2)} ms wall, p50 ${percentile(thread, 50).toFixed(2)} / `
        + `p99 ${percentile(thread, 99).toFixed(2)} ms on the thread, p50 ${percentile(script, 50).toFixed(2)} / `
        + `p99 ${percentile(script, 99).toFixed(2)} ms of all the thread's script`);
    }
  } finally {
    await browser.close();
    for (const server of servers) server.close();
  }
}

if (import.meta.url === `file://${process.argv[1]}`) {
  if (process.argv[2] === 'map') {
    const { browser, base, close } = await session('WebGL2');
    try {
      const one = await shapeMap(browser, base, 1);
      const two = await shapeMap(browser, base, 2);
      console.log(`the turbinate's map of 64 shells: 1 worker ${one.toFixed(2)} s, 2 workers ${two.toFixed(2)} s (× ${(one / two).toFixed(2)})`);
    } finally {
      await close();
    }
  } else if (process.argv[2] === 'gallery') {
    await benchGallery(process.argv[3]);
  } else if (process.argv[2] === 'frames') {
    const roots = process.argv.slice(3);
    await benchFrames(roots.length > 0 ? roots : [new URL('../../www/', import.meta.url).pathname],
      Number(process.env.ROUNDS ?? 2), Number(process.env.FRAMES ?? 100),
      (process.env.WORKERS ?? '1').split(',').flatMap((n) => (process.env.VIEWS ?? 'worker,page').split(',')
        .map((view) => `workers=${n}${view === 'page' ? '&view=page' : ''}`)),
      process.env.BACKEND ?? 'WebGL2');
  } else {
    await benchWorkers();
  }
}
