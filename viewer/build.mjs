// Bundles the viewer (src/main.js and three.js) into one minified IIFE script for view.html
// (docs/viewer.md). Usage: node build.mjs OUTFILE
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const here = path.dirname(fileURLToPath(import.meta.url));
const outfile = process.argv[2] ?? path.join(here, 'dist', 'attiguard_viewer.js');
await build({
  entryPoints: [path.join(here, 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: ['chrome100', 'firefox100', 'safari15'],
  legalComments: 'eof',
  outfile,
  logLevel: 'warning',
});
