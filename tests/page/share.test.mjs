// Sharing: on both backends, a frame-exact video of the growth (read back by mediabunny, a
// middle frame decoded by the browser's <video>); on WebGL2, embeds with ui=none and ui=controls inside a
// page of someone else's that keeps its focus and scroll, the QR code read back by jsQR; then,
// on WebGL2, cancelled and interrupted recordings, browsers without WebCodecs or any encoder,
// the title and the link-preview tags. Screenshots and frames go to tests/page/screenshots/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import jsQR from 'jsqr';
import { Input, BufferSource, ALL_FORMATS, EncodedPacketSink } from 'mediabunny';
import { serve } from './serve.mjs';
import { launch, open, waitForState, measureCanvas } from './browser.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = `${ROOT}tests/page/screenshots/`;
mkdirSync(SHOTS, { recursive: true });
// A shell of few triangles, grown at once: 30 growth frames (the one-second minimum at 30 fps).
const SHELL = 'v=1&preset=kawaguchi-claw&growth.speed=200';
// The same with a value changed, in the link's canonical form.
const EDITED = 'v=1&preset=kawaguchi-claw&form.chamber.width=0.5&growth.speed=200';
let server;
let base;

before(async () => {
  server = await serve(`${ROOT}www/`);
  base = `http://127.0.0.1:${server.address().port}/`;
});
after(() => server.close());

const dataset = (page) => page.evaluate(() => ({ ...document.body.dataset }));

/** What a third-party reader finds in a video file. */
async function readVideo(bytes) {
  const input = new Input({ source: new BufferSource(bytes), formats: ALL_FORMATS });
  const track = await input.getPrimaryVideoTrack();
  let packets = 0;
  let keys = 0;
  for await (const p of new EncodedPacketSink(track).packets()) {
    packets += 1;
    if (p.type === 'key') keys += 1;
  }
  return {
    mime: await input.getMimeType(),
    width: track.displayWidth,
    height: track.displayHeight,
    duration: await input.computeDuration(),
    packets,
    keys,
  };
}

/**
 * Decodes the frame at `time` seconds with the browser's own <video>, on a blank page (the
 * shell page's policy rightly allows no media), keeps it as a PNG, and measures it against its
 * corner's colour: the share of pixels that differ and their distinct shades.
 */
async function decodeFrame(browser, bytes, time, file) {
  const page = await browser.newPage();
  try {
    const frame = await page.evaluate(async ([data, t]) => {
      const video = document.createElement('video');
      video.muted = true;
      video.src = URL.createObjectURL(new Blob([new Uint8Array(data)], { type: 'video/webm' }));
      await new Promise((ok, no) => {
        video.onloadeddata = ok;
        video.onerror = () => no(new Error(`the video does not load: ${video.error?.message}`));
      });
      if (t === 'last') {
        // A MediaRecorder file has no duration in its header: a seek far past its end makes the
        // browser read it through, and then its last frame is a seek away.
        video.currentTime = 1e9;
        await new Promise((ok) => { video.onseeked = ok; });
        video.currentTime = Math.max(0, video.duration - 0.02);
      } else {
        video.currentTime = t;
      }
      await new Promise((ok) => { video.onseeked = ok; });
      const c = document.createElement('canvas');
      c.width = video.videoWidth;
      c.height = video.videoHeight;
      const g = c.getContext('2d');
      g.drawImage(video, 0, 0);
      const { data: px } = g.getImageData(0, 0, c.width, c.height);
      const bg = [px[0], px[1], px[2]];
      let differing = 0;
      const shades = new Set();
      for (let i = 0; i < px.length; i += 4) {
        if (Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]) > 24) {
          differing += 1;
          shades.add(((px[i] >> 4) << 8) | ((px[i + 1] >> 4) << 4) | (px[i + 2] >> 4));
        }
      }
      return { share: differing / (px.length / 4), shades: shades.size, duration: video.duration, png: c.toDataURL('image/png') };
    }, [[...bytes], time]);
    writeFileSync(file, Buffer.from(frame.png.split(',')[1], 'base64'));
    return frame;
  } finally {
    await page.close();
  }
}

/** Whether the canvas draws at its own size on the page again (no recording's fixed size). */
const canvasFits = (page) => page.evaluate(() => {
  const c = document.getElementById('shell');
  const dpr = window.devicePixelRatio;
  return c.width === Math.round(c.clientWidth * dpr) && c.height === Math.round(c.clientHeight * dpr)
    && !c.classList.contains('fixed');
});

/**
 * Opens `link` in the viewer and waits for the shell to be grown; the browser's encoders are
 * not asked for until Record is pressed.
 */
async function openShell(browser, link, viewport = { width: 1100, height: 760 }) {
  const opened = await open(browser, `${base}#${link}`, viewport);
  await waitForState(opened.page, ['grown']);
  assert.equal((await dataset(opened.page)).encoder, 'unasked');
  assert.match(await opened.page.textContent('#record-status'), /every frame of the growth; Record first asks the browser/);
  return opened;
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`a recording on ${backend} has one frame per growth frame plus the turntable, and shows the shell`, async () => {
    const browser = await launch(backend);
    try {
      const { page, errors } = await openShell(browser, SHELL);
      await page.selectOption('#record-size', '360');
      await page.selectOption('#record-fps', '30');
      await page.selectOption('#record-turntable', '3');
      const [download] = await Promise.all([
        page.waitForEvent('download', { timeout: 600_000 }),
        page.click('#record'),
      ]);
      assert.equal(download.suggestedFilename(), 'kawaguchi-claw-360p30.webm');
      const file = `${SHOTS}share-${backend}.webm`;
      await download.saveAs(file);
      const state = await dataset(page);
      assert.equal(state.encoder, 'VP9', 'the first codec the browser takes');
      assert.equal(state.record, 'saved');
      assert.equal(state.recordFrames, '120');
      assert.match(await page.textContent('#record-status'), /Saved kawaguchi-claw-360p30\.webm: 120 frames, 4\.00 s/);
      const video = await readVideo(readFileSync(file));
      assert.match(video.mime, /^video\/webm; codecs="vp09/);
      assert.equal(video.packets, 30 + 90, '30 growth frames and 3 s of turntable at 30 fps');
      assert.equal(video.keys, 2, 'a key frame every 2 s');
      assert.deepEqual([video.width, video.height], [640, 360]);
      assert.ok(Math.abs(video.duration - 4) < 1 / 30, `duration ${video.duration} s`);
      const middle = await decodeFrame(browser, readFileSync(file), 2.0, `${SHOTS}share-${backend}-frame.png`);
      assert.ok(Math.abs(middle.duration - 4) < 1 / 30, `the player reads ${middle.duration} s`);
      assert.ok(middle.share > 0.03, `the middle frame is blank: ${middle.share} of it differs from its corner`);
      assert.ok(middle.shades > 20, `the middle frame has only ${middle.shades} shades: not a lit shell`);
      // The page is itself again: drawn at its own size, and the controls work.
      assert.ok(await canvasFits(page), 'the canvas draws at its own size again');
      assert.equal(await page.isHidden('#record-cancel'), true);
      await page.keyboard.press('r');
      await waitForState(page, ['grown']);
      assert.deepEqual(errors, []);
    } finally {
      await browser.close();
    }
  });
}

// One backend: an embed is the page in a frame, drawn as the page is on both (the recording
// above); what this checks is the frame's layout, focus, scroll and the QR code.
for (const backend of ['WebGL2']) {
  test(`embeds on ${backend}: the shell alone or with its controls, inside a page that keeps its focus and scroll; the QR code reads back`, async () => {
    const browser = await launch(backend);
    try {
      // The QR code in the share panel holds the link.
      const { page, errors } = await openShell(browser, EDITED);
      const decoded = await page.evaluate(async () => {
        const img = document.getElementById('qr');
        await img.decode();
        const c = document.createElement('canvas');
        c.width = 320;
        c.height = 320;
        const g = c.getContext('2d');
        g.imageSmoothingEnabled = false;
        g.drawImage(img, 0, 0, 320, 320);
        return [...g.getImageData(0, 0, 320, 320).data];
      });
      const code = jsQR(Uint8ClampedArray.from(decoded), 320, 320);
      assert.ok(code, 'jsQR finds a QR code');
      assert.equal(code.data, `${base}#${EDITED}`);
      // The embed code for the shell alone.
      await page.selectOption('#embed-ui', 'none');
      await page.click('#copy-embed');
      const snippet = await page.inputValue('#embed-code');
      assert.equal(
        snippet,
        `<iframe src="${base}#${EDITED.replaceAll('&', '&amp;')}&amp;ui=none" title="Claw — Seashells" width="640" height="480" style="border:0" loading="lazy" allow="fullscreen"></iframe>`,
      );
      await page.close();
      assert.deepEqual(errors, []);

      for (const ui of ['none', 'controls']) {
        const embed = await open(browser, `${base}#${SHELL}&ui=${ui}`, { width: 640, height: 480 });
        const state = await waitForState(embed.page, ['grown']);
        assert.equal(state.ui, ui);
        for (const hidden of ['#gallery', '#panel', '.caption', '.planar', '#message']) {
          assert.equal(await embed.page.isVisible(hidden), false, `${hidden} is hidden with ui=${ui}`);
        }
        assert.equal(await embed.page.isVisible('.controls'), ui === 'controls');
        const box = await embed.page.locator('#shell').boundingBox();
        assert.deepEqual([box.x, box.y, box.width, box.height], [0, 0, 640, 480], 'the canvas fills the frame');
        const shot = await measureCanvas(embed.page, `${SHOTS}share-${backend}-ui-${ui}.png`);
        assert.ok(shot.share > 0.02, `the embedded shell covers ${shot.share}`);
        assert.equal(await embed.page.evaluate(() => location.hash.endsWith(`&ui=${document.body.dataset.ui}`)), true);
        assert.deepEqual(embed.errors, []);
        await embed.page.close();
      }

      // Inside someone else's page, the embed grows without taking focus or the wheel.
      const host = await browser.newPage({ viewport: { width: 900, height: 700 } });
      await host.route(`${base}host.html`, (route) => route.fulfill({
        contentType: 'text/html',
        body: `<!doctype html><title>A teacher's page</title><input id="note" value="typing here">
          <p style="height:300px">Before the shell.</p>${snippet.replace('loading="lazy" ', '')}
          <p style="height:2000px">After the shell.</p>`,
      }));
      await host.goto(`${base}host.html`);
      await host.focus('#note');
      const frame = host.frames().find((f) => f.url().includes('ui=none'));
      await frame.waitForFunction(() => document.body.dataset.state === 'grown', null, { timeout: 120_000 });
      assert.equal(await host.evaluate(() => document.activeElement.id), 'note', 'the page keeps its focus');
      assert.equal(await host.evaluate(() => window.scrollY), 0, 'the embed did not scroll the page');
      const box = await host.locator('iframe').boundingBox();
      await host.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await host.mouse.wheel(0, 400);
      await host.waitForFunction(() => window.scrollY > 0, null, { timeout: 5000 });
      await host.close();

      // A reader who asked for reduced motion gets the grown shell, still.
      const still = await browser.newPage({ viewport: { width: 640, height: 480 }, reducedMotion: 'reduce' });
      await still.goto(`${base}#v=1&preset=kawaguchi-claw&ui=none`);
      const grown = await waitForState(still, ['grown']);
      assert.equal(grown.playing, 'false');
      assert.equal(grown.rows, '25', 'grown at once although the link grows 0.2 rows a frame');
      await still.close();
    } finally {
      await browser.close();
    }
  });
}

test('a cancelled or interrupted recording leaves no file and a working page', async () => {
  const browser = await launch('WebGL2');
  try {
    const { page, errors } = await openShell(browser, SHELL);
    const downloads = [];
    page.on('download', (d) => downloads.push(d.suggestedFilename()));
    const interruptions = [
      ['you cancelled it', () => page.click('#record-cancel')],
      ['the tab was hidden', () => page.evaluate(() => {
        Object.defineProperty(document, 'hidden', { configurable: true, get: () => true });
        document.dispatchEvent(new Event('visibilitychange'));
        delete document.hidden;
      })],
      ['the shell was changed', () => page.evaluate(() => {
        const input = document.querySelector('[data-key="form.chamber.width"] input.number');
        input.value = input.value === '0.5' ? '0.55' : '0.5';
        input.dispatchEvent(new Event('change', { bubbles: true }));
      })],
    ];
    for (const [why, interrupt] of interruptions) {
      await page.click('#record');
      await page.waitForFunction(() => Number(document.body.dataset.recordFrames) >= 2);
      assert.equal(await page.isVisible('#record-progress'), true);
      await interrupt();
      await page.waitForFunction(() => document.body.dataset.record === 'cancelled');
      assert.equal(await page.textContent('#record-status'), `Recording cancelled: ${why}. Nothing was saved.`);
      assert.equal(await page.isVisible('#record'), true);
      assert.equal(await page.isVisible('#record-cancel'), false);
      await waitForState(page, ['grown']);
      assert.ok(await canvasFits(page), `after "${why}" the canvas draws at its own size`);
    }
    await page.waitForTimeout(1500);
    assert.deepEqual(downloads, [], 'no file was offered');
    await page.keyboard.press('Space');
    assert.equal((await dataset(page)).playing, 'false', 'the controls still work');
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
  }
});

test('without WebCodecs the page records with MediaRecorder and says so; without any encoder it says why', async () => {
  const browser = await launch('WebGL2');
  try {
    const context = await browser.newContext({ viewport: { width: 1100, height: 760 } });
    await context.addInitScript(() => { delete window.VideoEncoder; });
    const page = await context.newPage();
    await page.goto(`${base}#${SHELL}`);
    await waitForState(page, ['grown']);
    await page.selectOption('#record-size', '360');
    await page.selectOption('#record-turntable', '0');
    const saved = page.waitForEvent('download', { timeout: 120_000 });
    await page.click('#record');
    await page.waitForFunction(() => document.body.dataset.encoder === 'MediaRecorder');
    await page.waitForFunction(() => /Recording frame/.test(document.getElementById('record-status').textContent));
    assert.match(await page.textContent('#record-status'), /in real time with MediaRecorder: this browser has no WebCodecs video encoder.*uneven/);
    const download = await saved;
    assert.equal(download.suggestedFilename(), 'kawaguchi-claw-360p30.webm');
    const file = `${SHOTS}share-mediarecorder.webm`;
    await download.saveAs(file);
    const video = await readVideo(readFileSync(file));
    assert.deepEqual([video.width, video.height], [640, 360]);
    assert.ok(video.packets >= 10, `MediaRecorder wrote ${video.packets} frames of the second of growth`);
    // The frames MediaRecorder took are the shell the viewer drew for it. The claw grows from its
    // tip in real time, so how far it got by a given second depends on the machine: the last
    // frame is the whole claw on any machine.
    const last = await decodeFrame(browser, readFileSync(file), 'last', `${SHOTS}share-mediarecorder-frame.png`);
    assert.ok(last.share > 0.03, `the last frame is not the grown claw: ${last.share} of it differs from its corner`);
    assert.ok(last.shades > 20, `the frame has only ${last.shades} shades: not a lit shell`);
    await context.close();

    const bare = await browser.newContext({ viewport: { width: 1100, height: 760 } });
    await bare.addInitScript(() => { delete window.VideoEncoder; delete window.MediaRecorder; });
    const none = await bare.newPage();
    await none.goto(`${base}#${SHELL}`);
    await waitForState(none, ['grown']);
    await none.click('#record');
    await none.waitForFunction(() => document.body.dataset.encoder === 'none');
    const why = "This browser cannot record video: it has neither WebCodecs' VideoEncoder nor MediaRecorder.";
    assert.equal(await none.textContent('#record-status'), why);
    assert.equal(await none.getAttribute('#record', 'aria-disabled'), 'true');
    // A person can still press it (aria-disabled keeps it in the tab order): it says why again.
    await none.click('#record', { force: true });
    assert.equal(await none.textContent('#record-status'), why);
    assert.equal((await dataset(none)).record, undefined);
    await bare.close();
  } finally {
    await browser.close();
  }
});

test('the title names the shell shown and follows navigation; the page carries link-preview tags and their picture', async () => {
  const browser = await launch('WebGL2');
  try {
    const { page, errors } = await open(browser, base, { width: 1100, height: 760 });
    await waitForState(page, ['gallery']);
    assert.equal(await page.title(), 'Seashells');
    await page.click('a.card[data-preset="murex-cabritii"]');
    await page.waitForFunction(() => document.title === 'Murex cabritii — Seashells');
    await page.goBack();
    await page.waitForFunction(() => document.title === 'Seashells');
    await page.goto(`${base}#v=1&preset=oliva-porphyria`);
    await page.waitForFunction(() => document.title === 'Oliva porphyria — Seashells');
    const meta = await page.evaluate(() => Object.fromEntries(
      [...document.querySelectorAll('meta[property^="og:"], meta[name^="twitter:"]')]
        .map((m) => [m.getAttribute('property') ?? m.getAttribute('name'), m.content]),
    ));
    for (const key of ['og:title', 'og:description', 'og:image', 'og:image:alt', 'twitter:card', 'twitter:title', 'twitter:description', 'twitter:image']) {
      assert.ok(meta[key]?.length > 0, `${key} is set`);
    }
    assert.equal(meta['twitter:card'], 'summary_large_image');
    const png = readFileSync(`${ROOT}www/${meta['og:image']}`);
    assert.equal(png.readUInt32BE(16), Number(meta['og:image:width']));
    assert.equal(png.readUInt32BE(20), Number(meta['og:image:height']));
    assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [1200, 630]);
    // An unknown interface opens the whole page and says so.
    await page.goto(`${base}#v=1&preset=turbinate&ui=sidebar`);
    await waitForState(page, ['growing', 'grown']);
    assert.equal((await dataset(page)).ui, 'full');
    assert.equal(await page.isVisible('#panel'), true);
    assert.match(await page.textContent('#message'), /ui: 'sidebar' is not one of full, controls, none; opened the full interface/);
    // The share controls sit together and answer to the keyboard by their names.
    const names = await page.$$eval('#share button, #share select, #share img, .downloads button',
      (es) => es.map((e) => e.getAttribute('aria-label') || e.alt || e.labels?.[0]?.textContent.trim().split('\n')[0] || e.textContent.trim()));
    for (const name of ['Copy link', 'Copy embed code', 'Record', "QR code of this shell's link", 'Picture']) {
      assert.ok(names.some((n) => n.startsWith(name)), `${name} is among ${names.join(', ')}`);
    }
    await page.focus('#copy-link');
    const order = [];
    for (let i = 0; i < 6; i += 1) {
      order.push(await page.evaluate(() => document.activeElement.id));
      await page.keyboard.press('Tab');
    }
    assert.deepEqual(order, ['copy-link', 'copy-embed', 'embed-ui', 'record-size', 'record-fps', 'record-turntable']);
    await page.focus('#record');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => document.body.dataset.record === 'recording');
    await page.focus('#record-cancel');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => document.body.dataset.record === 'cancelled');
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
  }
});
