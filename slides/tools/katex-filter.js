#!/usr/bin/env node
// katex-filter.js: typesets the decks' math at build time, so neither the
// HTML deck nor the PDF (WeasyPrint runs no JavaScript) needs a script to
// show an equation.
//
//   pandoc --filter slides/tools/katex-filter.js ...   a pandoc JSON filter: every
//        $...$ and $$...$$ becomes KaTeX's HTML; a TeX error stops the build
//        and names the deck's formula
//   node slides/tools/katex-filter.js --css woff2|ttf   KaTeX's stylesheet with
//        its fonts as absolute paths of one format (woff2 for browsers, ttf
//        for WeasyPrint), for pandoc to embed
//
// KaTeX comes from Debian's libjs-katex and fonts-katex (or the npm package
// where that is installed); nothing is fetched.
'use strict';
const fs = require('fs');
const path = require('path');

const candidates = [
  process.env.SL_KATEX_JS,
  '/usr/share/javascript/katex/katex.min.js',   // Debian libjs-katex (12, 13, testing)
  '/usr/share/nodejs/katex/dist/katex.min.js',  // Debian's katex package
  path.join(__dirname, '..', '..', 'node_modules', 'katex', 'dist', 'katex.min.js'),
].filter(Boolean);
const katexJs = candidates.find((p) => fs.existsSync(p));
function die(msg) { process.stderr.write(`katex-filter: ${msg}\n`); process.exit(1); }
if (!katexJs) die(`KaTeX not found (looked in ${candidates.join(', ')}); run scripts/install-slides-deps.sh`);
const katex = require(katexJs);
const distDir = path.dirname(fs.realpathSync(katexJs));

if (process.argv[2] === '--css') {
  const format = process.argv[3] || 'woff2';
  const cssPath = path.join(distDir, 'katex.min.css');
  let css = fs.readFileSync(cssPath, 'utf8');
  const fontsDir = fs.realpathSync(path.join(distDir, 'fonts'));
  // Each @font-face lists woff2, woff and ttf: keep the one format asked for, as an absolute path.
  css = css.replace(/src:([^;}]*)/g, (all, list) => {
    const m = list.match(new RegExp(`url\\(fonts/([^)]+\\.${format})\\)\\s*format\\(['"][^'"]+['"]\\)`));
    if (!m) return all;
    return `src:url(${path.join(fontsDir, m[1])}) format("${format === 'ttf' ? 'truetype' : format}")`;
  });
  process.stdout.write(css);
  process.exit(0);
}

// A pandoc filter: read the document's JSON AST, typeset every Math element.
const chunks = [];
process.stdin.on('data', (c) => chunks.push(c));
process.stdin.on('end', () => {
  const doc = JSON.parse(Buffer.concat(chunks).toString('utf8'));
  let errors = 0;
  const deck = process.env.SL_DECK || 'a deck';
  const walk = (node) => {
    if (Array.isArray(node)) {
      for (let i = 0; i < node.length; i++) node[i] = walk(node[i]);
      return node;
    }
    if (node && typeof node === 'object') {
      if (node.t === 'Math') {
        const display = node.c[0].t === 'DisplayMath';
        const tex = node.c[1];
        try {
          const html = katex.renderToString(tex, { displayMode: display, throwOnError: true, output: 'html', strict: 'error' });
          return { t: 'RawInline', c: ['html', html] };
        } catch (e) {
          errors++;
          process.stderr.write(`katex-filter: ${deck}: cannot typeset $${tex}$: ${e.message}\n`);
          return node;
        }
      }
      for (const k of Object.keys(node)) node[k] = walk(node[k]);
    }
    return node;
  };
  walk(doc.blocks);
  if (errors) process.exit(1);
  process.stdout.write(JSON.stringify(doc));
});
