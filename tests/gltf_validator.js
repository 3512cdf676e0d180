// Runs the Khronos glTF validator (npm package gltf-validator, unpacked by tests/scenes_test.py)
// on glTF files and prints one JSON line per file: its counts of errors, warnings, infos and hints,
// and every message. External buffers and images are read relative to the file.
// Usage: node tests/gltf_validator.js VALIDATOR_DIR FILE...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(path.resolve(process.argv[2]));

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,  // every issue, not the first 100
    writeTimestamp: false,
    externalResourceFunction: (uri) =>
      fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))),
  });
  const issues = report.issues;
  return {
    file, version: report.validatorVersion, errors: issues.numErrors,
    warnings: issues.numWarnings, infos: issues.numInfos, hints: issues.numHints,
    messages: issues.messages.map((m) => ({code: m.code, severity: m.severity,
                                           pointer: m.pointer, message: m.message})),
  };
}

(async () => {
  for (const file of process.argv.slice(3)) {
    console.log(JSON.stringify(await validate(file)));
  }
})().catch((error) => {
  console.error(`gltf_validator.js: ${error}`);
  process.exit(1);
});
