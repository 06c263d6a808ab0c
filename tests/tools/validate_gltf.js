// Validates a .glb with the Khronos glTF validator; prints the report summary as JSON and
// exits 1 when it has errors. Usage: node validate_gltf.js FILE.glb
const fs = require('fs');
const validator = require('gltf-validator');
const file = process.argv[2];
const data = new Uint8Array(fs.readFileSync(file));
validator.validateBytes(data, {maxIssues: 20}).then((report) => {
  const i = report.issues;
  console.log(JSON.stringify({errors: i.numErrors, warnings: i.numWarnings, infos: i.numInfos,
    messages: i.messages.slice(0, 10), info: report.info}, null, 1));
  process.exit(i.numErrors > 0 ? 1 : 0);
}).catch((e) => { console.error(String(e)); process.exit(2); });
