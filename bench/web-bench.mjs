// make bench's web row: the course example at 768x768 rendered by the page
// (build/web/index.html opened from disk in headless chromium, with as
// many workers as THREADS) against build/whitted with -j THREADS, runs
// alternating, medians of RUNS; the page's size and its time from opening
// to the first image (the median of RUNS fresh pages).  The page's time is
// window.whitted.render's (every worker reading the scene and building its
// hierarchy, then the bands of rows); the CLI's the whole process's,
// writing a PPM.  Usage: node web-bench.mjs PAGE WHITTED SCENE MODULES
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { createRequire } from 'node:module';

const [page, whitted, scene, modules] = process.argv.slice(2);
const { chromium } = createRequire(path.resolve(modules, 'x.js'))('playwright-core');
const runs = Number(process.env.RUNS || 5), threads = Number(process.env.THREADS || 2);
const median = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
const firsts = [];
let p;
for (let i = 0; i < runs; i++) {
  const ctx = await browser.newContext();
  p = await ctx.newPage();
  await p.goto(pathToFileURL(page).href);
  await p.waitForSelector('body[data-rendered="1"]', { timeout: 60000 });
  firsts.push(await p.evaluate(() => performance.now()));
  if (i < runs - 1)
    await ctx.close();
}
const text = fs.readFileSync(scene, 'utf8');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'whitted-webbench-'));
const pageTimes = [], cliTimes = [];
// One untimed render each: the page's WebAssembly reaches its optimised tier.
await p.evaluate(async ([t, n]) => whitted.render(t, { threads: n }), [text, threads]);
for (let i = 0; i < runs; i++) {
  pageTimes.push(await p.evaluate(async ([t, n]) => {
    const t0 = performance.now();
    await whitted.render(t, { threads: n });
    return performance.now() - t0;
  }, [text, threads]));
  const t0 = process.hrtime.bigint();
  const r = spawnSync(whitted, ['-q', '-j', String(threads), '-o', path.join(tmp, 'x.ppm'), scene]);
  cliTimes.push(Number(process.hrtime.bigint() - t0) / 1e6);
  if (r.status !== 0)
    throw new Error('whitted failed: ' + r.stderr);
}
await browser.close();
fs.rmSync(tmp, { recursive: true, force: true });
const workers = Math.min(threads, os.cpus().length);
const dir = path.dirname(page);
const bytes = fs.readdirSync(dir).reduce((s, f) => s + fs.statSync(path.join(dir, f)).size, 0);
const pm = median(pageTimes) / 1000, cm = median(cliTimes) / 1000;
console.log('');
console.log('| web page (headless chromium) | size | page s | whitted s | page / whitted | page folder | first image |');
console.log('|---|---|---|---|---|---|---|');
console.log('| example, ' + workers + ' workers / -j ' + threads + ' | 768 | ' + pm.toFixed(3) + ' | ' + cm.toFixed(3) +
  ' | ' + (pm / cm).toFixed(2) + ' | ' + (bytes / 1048576).toFixed(2) + ' MiB | ' +
  (median(firsts) / 1000).toFixed(2) + ' s |');
