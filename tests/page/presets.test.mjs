// Every preset in species/ grows to a visible, lit shell in the page, with no console errors
// and no message; each once, the two backends taking turns down the sorted list, so that every
// kind of form (swept, implicit, Kawaguchi's chambers and branching) is drawn on both.
// Screenshots are kept for looking.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readdirSync } from 'node:fs';
import { growPreset, session } from './browser.mjs';

const SHOTS = new URL('./screenshots/presets/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
const IDS = readdirSync(new URL('../../species/', import.meta.url))
  .filter((f) => f.endsWith('.json'))
  .map((f) => f.slice(0, -5))
  .sort();
const BACKENDS = ['WebGL2', 'WebGPU'];
const sessions = {};

before(async () => {
  for (const backend of BACKENDS) sessions[backend] = await session(backend);
});
after(() => Promise.all(Object.values(sessions).map((s) => s.close())));

IDS.forEach((id, i) => {
  const backend = BACKENDS[i % 2];
  test(`preset ${id} grows into a shell on ${backend}`, async () => {
    const { browser, base } = sessions[backend];
    const state = await growPreset(browser, base, id, `${SHOTS}${id}.png`);
    assert.equal(state.backend, backend);
  });
});

test('every kind of form is grown on both backends', () => {
  const kind = (id) => (id.startsWith('kawaguchi-') ? 'kawaguchi' : /^(implicit|murex)-/.test(id) ? 'implicit' : 'swept');
  for (const k of ['swept', 'implicit', 'kawaguchi']) {
    const on = new Set(IDS.map((id, i) => [id, BACKENDS[i % 2]]).filter(([id]) => kind(id) === k).map(([, b]) => b));
    assert.deepEqual([...on].sort(), BACKENDS, `${k} forms are grown on ${[...on]}`);
  }
});
