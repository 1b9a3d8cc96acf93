// What the native core (the command line, `seashells`) makes of a link: the page's tests
// compare the shell grown in the page with it, bit for bit where the platforms agree. The
// command line is $SEASHELLS (make test passes the test profile's build, which `cargo test`
// has built already), or the release build.
import { execFileSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

export const CLI = resolve(
  new URL('../../', import.meta.url).pathname,
  process.env.SEASHELLS ?? 'target/release/seashells',
);
const known = new Map();

/** Runs the command line once per distinct call and remembers what it printed. */
function run(args) {
  const key = args.join('\u0000');
  if (!known.has(key)) known.set(key, execFileSync(CLI, args).toString());
  return known.get(key);
}

/** The hash of the pattern the native core computes for a link (`v=1&…`, no `#`). */
export function nativePattern(link, out = join(tmpdir(), `seashells-native-${process.pid}.png`)) {
  return /hash ([0-9a-f]{16})/.exec(run(['pattern', '--link', link, '--out', out]))[1];
}

/**
 * The mesh the native core makes of a link: its counts as the page says them ("N vertices, M
 * triangles"), its hash, and the line the command line printed. `out` names the file written
 * (its extension its format), for tests that read the file too.
 */
export function nativeMesh(link, out = join(tmpdir(), `seashells-native-${process.pid}.stl`)) {
  const said = run(['mesh', '--link', link, '--out', out]);
  const [, counts, hash] = /: (\d+ vertices, \d+ triangles), hash ([0-9a-f]{16})/.exec(said);
  return { counts, hash, said };
}
