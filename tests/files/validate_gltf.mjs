// Validates glTF files with the Khronos glTF Validator (npm gltf-validator): prints, for each
// file named on the command line, one JSON line of the report's counts, its messages and what
// it found (textures, texture coordinates, triangles).
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';

const validator = createRequire(import.meta.url)('gltf-validator');

for (const path of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(await readFile(path)), { maxIssues: 50 });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  console.log(JSON.stringify({
    path,
    numErrors,
    numWarnings,
    numInfos,
    numHints,
    messages: messages.map(({ code, severity, pointer, message }) => ({ code, severity, pointer, message })),
    info: report.info,
  }));
}
