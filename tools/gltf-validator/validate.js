// SPDX-License-Identifier: Zlib
// Validates .glb/.gltf files with the Khronos glTF-Validator (npm gltf-validator, installed next
// to this file by scripts/install-deps.sh) and prints each file's issue counts and its errors and
// warnings. Exits 1 when a file has an error (or cannot be read), 0 otherwise.
//   node validate.js FILE...
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

async function main(files) {
  if (files.length === 0) {
    console.error('usage: node validate.js FILE...');
    return 2;
  }
  let failed = false;
  for (const file of files) {
    let report;
    try {
      report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {maxIssues: 100});
    } catch (error) {
      console.error(`${file}: ${error.message || error}`);
      failed = true;
      continue;
    }
    const issues = report.issues;
    const info = report.info || {};
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos, ` +
                `${info.drawCallCount} draw calls, ${info.animationCount} animations, ${info.totalTriangleCount} triangles`);
    for (const message of issues.messages)
      if (message.severity <= 1)
        console.log(`  ${message.severity === 0 ? 'error' : 'warning'} ${message.code} ${message.pointer || ''}: ` +
                    message.message);
    failed = failed || issues.numErrors > 0;
  }
  return failed ? 1 : 0;
}

main(process.argv.slice(2)).then((code) => process.exit(code));
