// The three browser engines the page is tested on, driven the same way: Chromium (Debian's,
// headless, through playwright-core, WebGL2 on SwiftShader), Firefox ESR (Debian's, headed,
// through puppeteer-core over WebDriver BiDi) and WebKitGTK (Debian's MiniBrowser, headed,
// through WebKitWebDriver over classic WebDriver, spoken here with fetch). Headed browsers
// need a display: `make test` runs the suite under xvfb-run, where Mesa's llvmpipe gives
// Firefox and WebKit WebGL2 (headless Firefox has none). See ../shared/TOOLCHAIN.md.
//
// A page offers: goto, evaluate (a function and one argument, both sent as JSON), waitFor, a
// PNG of an element as shown, click, the bytes of a file the page offers for download (caught
// before the browser's own download, which differs between engines and their headed modes),
// and the console errors and uncaught exceptions seen since the page was opened.
import { spawn } from 'node:child_process';
import { closeSync, openSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createServer } from 'node:net';
import { PNG } from 'pngjs';
import { chromium } from 'playwright-core';
import puppeteer from 'puppeteer-core';
import { BACKENDS } from './browser.mjs';

export { measurePng as measure } from './browser.mjs';

export const ENGINES = ['chromium', 'firefox', 'webkit'];

const MINIBROWSER = '/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser';
const CHROMIUM_FLAGS = [
  '--no-sandbox', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-quic', ...BACKENDS.WebGL2,
];

/**
 * Installed in every page: keeps console errors and uncaught exceptions (WebKit's driver
 * reports none), and the files the page offers for download by name, instead of handing them
 * to the browser.
 */
function hooks() {
  if (window.__seen) return;
  window.__seen = { errors: [], files: {}, frames: 0 };
  // Counts the animation frames the browser gives the page: a page that never starts growing
  // says in a timeout's message whether it was given any.
  const frame = () => { window.__seen.frames += 1; requestAnimationFrame(frame); };
  requestAnimationFrame(frame);
  const error = console.error.bind(console);
  console.error = (...args) => { window.__seen.errors.push(args.map(String).join(' ')); error(...args); };
  window.addEventListener('error', (e) => window.__seen.errors.push(String(e.message)));
  window.addEventListener('unhandledrejection', (e) => window.__seen.errors.push(String(e.reason)));
  const blobs = new Map();
  const make = URL.createObjectURL.bind(URL);
  URL.createObjectURL = (blob) => { const url = make(blob); blobs.set(url, blob); return url; };
  const click = HTMLAnchorElement.prototype.click;
  HTMLAnchorElement.prototype.click = function () {
    if (this.download && blobs.has(this.href)) {
      window.__seen.files[this.download] = blobs.get(this.href);
      return;
    }
    click.call(this);
  };
}

/** Reads the bytes of a file the page offered, as base64 (run in the page). */
async function readFile(name) {
  const blob = window.__seen.files[name];
  if (!blob) return null;
  const bytes = new Uint8Array(await blob.arrayBuffer());
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

/** A free port on the loopback interface. */
function freePort() {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

/**
 * What a page shows of itself, for a timeout's message: its signals, its status lines, the
 * animation frames it was given, whether it is visible, and its errors.
 */
function shown() {
  const text = (id) => document.getElementById(id)?.textContent?.trim() ?? '';
  return JSON.stringify({
    ...document.body.dataset,
    workers: text('workers-status'),
    message: text('message'),
    frames: window.__seen?.frames,
    visibility: document.visibilityState,
    errors: window.__seen?.errors,
  });
}

/** A page of any engine, around `driver` (goto, run, element PNG, click, logged errors). */
class Page {
  constructor(driver) {
    this.driver = driver;
  }

  async goto(url) {
    await this.driver.goto(url);
    await this.driver.run(hooks, null);
  }

  /** Runs `fn(arg)` in the page and returns its (JSON) result, awaiting a promise. */
  evaluate(fn, arg = null) {
    return this.driver.run(fn, arg);
  }

  /** Waits until `fn(arg)` is truthy in the page, polling; fails after `timeout` ms. */
  async waitFor(fn, arg = null, timeout = 120_000, what = String(fn)) {
    const until = Date.now() + timeout;
    for (;;) {
      const value = await this.evaluate(fn, arg);
      if (value) return value;
      if (Date.now() > until) throw new Error(`timed out after ${timeout} ms waiting for ${what}; the page shows ${await this.evaluate(shown)}`);
      await new Promise((r) => setTimeout(r, 250));
    }
  }

  /** The page's signals on <body>. */
  dataset() {
    return this.evaluate(() => ({ ...document.body.dataset }));
  }

  /** Waits until <body data-state> is one of `states`; returns the signals. */
  async waitForState(states, timeout = 180_000) {
    await this.waitFor((wanted) => wanted.includes(document.body.dataset.state), states, timeout, `state ${states}`);
    return this.dataset();
  }

  /** The element `selector` as shown, as PNG bytes. */
  shot(selector) {
    return this.driver.shot(selector);
  }

  /** Clicks the element `selector` as a person would. */
  click(selector) {
    return this.driver.click(selector);
  }

  /** Clicks `selector` and returns the bytes of the file `name` the page then offers. */
  async download(selector, name, timeout = 180_000) {
    await this.evaluate((n) => { delete window.__seen.files[n]; }, name);
    await this.click(selector);
    await this.waitFor((n) => Boolean(window.__seen.files[n]), name, timeout, `the file ${name}`);
    return Buffer.from(await this.driver.run(readFile, name), 'base64');
  }

  /** What the page said on the console, but its errors (where the engine tells). */
  said() {
    return this.driver.said;
  }

  /** Console errors and uncaught exceptions so far. */
  async errors() {
    const seen = await this.evaluate(() => window.__seen?.errors ?? []);
    return [...new Set([...this.driver.logged, ...seen])];
  }

  close() {
    return this.driver.close();
  }
}

/**
 * A page of playwright's or puppeteer's (their pages answer alike), `shot` reading an element's
 * PNG.
 */
function listened(page, shot) {
  const [logged, said] = [[], []];
  page.on('console', (m) => { (m.type() === 'error' ? logged : said).push(m.text()); });
  page.on('pageerror', (e) => logged.push(String(e)));
  return new Page({
    logged,
    said,
    goto: (url) => page.goto(url),
    run: (fn, arg) => page.evaluate(fn, arg),
    shot,
    click: (selector) => page.click(selector),
    close: () => page.close(),
  });
}

/** Chromium through playwright-core. */
async function chromiumEngine() {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: CHROMIUM_FLAGS,
  });
  return {
    version: browser.version(),
    async newPage(viewport) {
      const page = await browser.newPage({ viewport });
      return listened(page, (selector) => page.locator(selector).screenshot());
    },
    close: () => browser.close(),
  };
}

/** Firefox ESR through puppeteer-core (WebDriver BiDi), headed. */
async function firefoxEngine() {
  const browser = await puppeteer.launch({
    browser: 'firefox',
    executablePath: process.env.FIREFOX ?? '/usr/bin/firefox-esr',
    headless: false,
    protocolTimeout: 120_000,
    defaultViewport: null,
  });
  return {
    version: await browser.version(),
    async newPage(viewport) {
      const page = await browser.newPage();
      await page.setViewport(viewport);
      return listened(page, async (selector) => Buffer.from(await (await page.$(selector)).screenshot()));
    },
    close: () => browser.close(),
  };
}

/**
 * One WebKitWebDriver process and the MiniBrowsers it opens, in a process group of their own so
 * that a driver that stops answering is killed with its windows. `call` sends one WebDriver
 * command and gives up after `timeout` ms.
 */
/**
 * Where WebKitWebDriver and its browsers write what they say (a web process that crashed says
 * so there; one that hangs does not): the tail is added to an error of a page that crashed or
 * hung, to tell the two apart.
 */
const WEBKIT_LOG = join(tmpdir(), `seashells-webkit-${process.pid}.log`);

/** The last `lines` lines the WebKit driver and its browsers wrote. */
function webkitSaid(lines = 40) {
  try {
    return readFileSync(WEBKIT_LOG, 'utf8').trimEnd().split('\n').slice(-lines).join('\n');
  } catch {
    return '(nothing)';
  }
}

async function webkitDriver() {
  const port = await freePort();
  const log = openSync(WEBKIT_LOG, 'a');
  const driver = spawn('WebKitWebDriver', [`--port=${port}`], { stdio: ['ignore', log, log], detached: true });
  closeSync(log);
  const call = async (method, path, body, timeout = 300_000) => {
    const response = await fetch(`http://127.0.0.1:${port}${path}`, {
      method,
      headers: { 'content-type': 'application/json' },
      body: body === undefined ? undefined : JSON.stringify(body),
      signal: AbortSignal.timeout(timeout),
    });
    const { value } = await response.json();
    if (value && value.error) {
      const said = /crash or hang/.test(value.message) ? `\nWebKit said:\n${webkitSaid()}` : '';
      throw new Error(`WebKitWebDriver ${path}: ${value.error}: ${value.message}${said}`);
    }
    return value;
  };
  for (let tries = 0; ; tries += 1) {
    try {
      await call('GET', '/status', undefined, 1_000);
      break;
    } catch (e) {
      if (tries > 100) throw e;
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  const kill = () => {
    try {
      process.kill(-driver.pid, 'SIGKILL');
    } catch {
      // Already gone.
    }
  };
  return { call, kill };
}

/**
 * WebKitGTK's MiniBrowser through WebKitWebDriver (classic WebDriver), headed. Now and then the
 * driver never answers a request for a new window (seen twice in fresh-clone runs of the suite):
 * a window that is not open within a minute is asked for again of a new driver.
 */
async function webkitEngine() {
  let driver = await webkitDriver();
  const call = (...args) => driver.call(...args);
  const sessions = [];
  const open = async () => {
    for (let attempt = 1; ; attempt += 1) {
      try {
        const { sessionId, capabilities } = await call('POST', '/session', {
          capabilities: { alwaysMatch: { 'webkitgtk:browserOptions': { binary: MINIBROWSER, args: ['--automation'] } } },
        }, 60_000);
        sessions.push(sessionId);
        return { id: sessionId, version: capabilities.browserVersion };
      } catch (e) {
        if (attempt === 3) throw e;
        console.error(`WebKitWebDriver opened no window (${e.message}): starting a new driver`);
        driver.kill();
        sessions.length = 0;
        driver = await webkitDriver();
      }
    }
  };
  const first = await open();
  await call('DELETE', `/session/${first.id}`);
  sessions.splice(sessions.indexOf(first.id), 1);
  const element = async (id, selector) => {
    const found = await call('POST', `/session/${id}/element`, { using: 'css selector', value: selector });
    return Object.values(found)[0];
  };
  return {
    version: first.version,
    async newPage(viewport) {
      const { id } = await open();
      // The window is the page's viewport plus the MiniBrowser's toolbar.
      const inner = await call('POST', `/session/${id}/execute/sync`, {
        script: 'return [window.outerWidth - window.innerWidth, window.outerHeight - window.innerHeight]',
        args: [],
      });
      await call('POST', `/session/${id}/window/rect`, { width: viewport.width + inner[0], height: viewport.height + inner[1] });
      return new Page({
        logged: [],
        said: [],
        goto: (url) => call('POST', `/session/${id}/url`, { url }),
        run: async (fn, arg) => {
          // The driver runs its script outside the page's Content-Security-Policy, which
          // allows no eval: the function is part of the script's text.
          const outcome = await call('POST', `/session/${id}/execute/async`, {
            script: `const [arg, done] = arguments;
              Promise.resolve().then(() => (${fn})(arg))
                .then((value) => done({ value: value === undefined ? null : value }), (e) => done({ error: String(e && e.stack || e) }));`,
            args: [arg],
          });
          if (outcome.error) throw new Error(outcome.error);
          return outcome.value;
        },
        // WebKitGTK's element screenshots come out black but for canvases: the element is
        // cut out of a screenshot of the window instead.
        shot: async (selector) => {
          const rect = await call('POST', `/session/${id}/execute/sync`, {
            script: `const e = document.querySelector(arguments[0]);
              e.scrollIntoView({ block: 'nearest' });
              const r = e.getBoundingClientRect();
              return [r.left, r.top, r.width, r.height, window.devicePixelRatio];`,
            args: [selector],
          });
          const window = PNG.sync.read(Buffer.from(await call('GET', `/session/${id}/screenshot`), 'base64'));
          const [x, y, w, h] = rect.slice(0, 4).map((v) => Math.round(v * rect[4]));
          const [left, top] = [Math.max(0, x), Math.max(0, y)];
          const [width, height] = [Math.min(window.width, x + w) - left, Math.min(window.height, y + h) - top];
          const part = new PNG({ width, height });
          PNG.bitblt(window, part, left, top, width, height, 0, 0);
          return PNG.sync.write(part);
        },
        click: async (selector) => call('POST', `/session/${id}/element/${await element(id, selector)}/click`, {}),
        close: async () => {
          await call('DELETE', `/session/${id}`).catch(() => {});
          sessions.splice(sessions.indexOf(id), 1);
        },
      });
    },
    async close() {
      for (const id of [...sessions]) await call('DELETE', `/session/${id}`, undefined, 10_000).catch(() => {});
      driver.kill();
    },
  };
}

/** Launches `engine` (one of [`ENGINES`]): `{ version, newPage(viewport), close() }`. */
export function launchEngine(engine) {
  if (engine !== 'chromium' && !process.env.DISPLAY) {
    throw new Error(`${engine} runs headed and needs a display: run the suite under xvfb-run (make test does)`);
  }
  return { chromium: chromiumEngine, firefox: firefoxEngine, webkit: webkitEngine }[engine]();
}

