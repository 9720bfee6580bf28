// Runs the Khronos glTF validator (npm package gltf-validator) over every
// .gltf and .glb file in the folder given as the only argument. Exit codes:
//   0   every file validated with no errors and no warnings
//   1   a file has errors or warnings, or there was nothing to validate
//   77  the validator is not installed (ctest reports the test as skipped)
'use strict';

const fs = require('fs');
const path = require('path');

let validator;
try {
    validator = require('gltf-validator');
} catch (e) {
    console.log('SKIPPED: the Khronos glTF validator is not installed. Install it with\n'
        + '    npm ci --prefix ' + __dirname + '\n'
        + '(needs Node.js and npm; scripts/dev.sh does this).');
    process.exit(77);
}

const folder = process.argv[2];
if (!folder || !fs.existsSync(folder)) {
    console.error('usage: node validate.js FOLDER (no such folder: ' + folder + ')');
    process.exit(1);
}
const files = fs.readdirSync(folder)
    .filter((name) => /\.(gltf|glb)$/i.test(name))
    .sort()
    .map((name) => path.join(folder, name));
if (files.length === 0) {
    console.error('no .gltf or .glb files in ' + folder);
    process.exit(1);
}

async function validate(file) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    return validator.validateBytes(bytes, {
        uri: path.basename(file),
        maxIssues: 0, // report all of them
        externalResourceFunction: (uri) => new Promise((resolve, reject) => {
            fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) => {
                if (err)
                    reject(err.toString());
                else
                    resolve(new Uint8Array(data));
            });
        }),
    });
}

(async () => {
    let failed = 0;
    console.log('gltf-validator ' + validator.version());
    for (const file of files) {
        let report;
        try {
            report = await validate(file);
        } catch (e) {
            console.log('FAIL ' + file + ': the validator could not read it: ' + e);
            ++failed;
            continue;
        }
        const issues = report.issues;
        const bad = issues.numErrors + issues.numWarnings;
        console.log((bad ? 'FAIL ' : 'ok   ') + path.basename(file) + ': ' + issues.numErrors + ' errors, '
            + issues.numWarnings + ' warnings, ' + issues.numInfos + ' infos, ' + issues.numHints + ' hints');
        for (const m of issues.messages) {
            const severity = ['error', 'warning', 'info', 'hint'][m.severity] || String(m.severity);
            console.log('     ' + severity + ' ' + m.code + ' at ' + (m.pointer || m.offset || '') + ': ' + m.message);
        }
        if (bad)
            ++failed;
    }
    console.log(files.length - failed + ' passed, ' + failed + ' failed');
    process.exit(failed ? 1 : 0);
})();
