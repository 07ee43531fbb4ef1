// check.mjs BOOK SHOTS [CHROMIUM] - every page of the book (BOOK, as
// build.sh writes it) in headless Chromium.
//
// Each page is loaded at 1280 pixels wide and fails on: an error in the
// console or a script, a failed request, an image that does not load
// (natural width 0), an equation left as raw TeX or rendered as an error, a
// link to a file that does not exist or to an anchor its page does not have
// (links out of the book are counted, not followed: there is no network).
// Then at 400 pixels wide, it fails when the page is wider than the window.
// Screenshots of the title page and of chapters 06 and 09, at both widths
// (top of the page; for a chapter also its first displayed equation), go
// to SHOTS.  A chapter's lesson page (NN_name.html, not its lab's pages) without a typeset equation fails too.  Prints one line per problem and a summary; exits 1 on any problem.
import { readdirSync, statSync, existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { join, resolve, relative } from 'node:path';
import { pathToFileURL, fileURLToPath } from 'node:url';
import { launch } from './cdp.mjs';

const [book, shots, chromium = '/usr/bin/chromium'] = process.argv.slice(2);
if (!book || !shots) {
    console.error('usage: check.mjs BOOK SHOTS [CHROMIUM]');
    process.exit(2);
}
const root = resolve(book);
const DESKTOP = { width: 1280, height: 900 }, PHONE = { width: 400, height: 860 };
const SHOT_PAGES = ['index.html', '06_shadows.html', '09_refraction.html'];

function htmlFiles(dir) {
    return readdirSync(dir).flatMap((name) => {
        const path = join(dir, name);
        if (statSync(path).isDirectory()) return name === 'katex' ? [] : htmlFiles(path);
        return name.endsWith('.html') ? [path] : [];
    }).sort();
}

// What the checks need from a loaded page, gathered in the page.
const INSPECT = `(async () => {
    await document.fonts.ready;
    const skip = (n) => n.closest('pre, code, script, style, .katex, .math');
    const raw = [];
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    const tex = /\\$[^\\s$][^$]*\\$|\\$\\$|\\\\(frac|sqrt|mathbf|cdot|tag|left|right|begin|end|alpha|beta|gamma|eta|theta|quad|times|le|ge)(?![a-z])/;
    for (let n = walker.nextNode(); n; n = walker.nextNode())
        if (!skip(n.parentElement) && tex.test(n.data)) raw.push(n.data.trim().slice(0, 80));
    const maths = [...document.querySelectorAll('.math')];
    return {
        images: [...document.images].map((i) => ({ src: i.currentSrc || i.src, width: i.naturalWidth, complete: i.complete })),
        equations: maths.length,
        unrendered: maths.filter((m) => !m.querySelector('.katex, .katex-error')).map((m) => m.textContent.slice(0, 80)),
        errors: [...document.querySelectorAll('.katex-error')].map((e) => e.title || e.textContent.slice(0, 80)),
        raw,
        links: [...document.querySelectorAll('a[href]')].map((a) => a.href),
        ids: [...document.querySelectorAll('[id]')].map((e) => e.id),
    };
})()`;
// The page's width; a phone's browser would widen its window to it and zoom out.
const WIDTH = `document.documentElement.scrollWidth`;

const started = Date.now();
const problems = [];
const files = htmlFiles(root);
const ids = new Map(); // file path -> Set of ids
const links = []; // [page, href]
let equations = 0, images = 0;
if (files.length === 0) {
    console.error(`check-book: ${book} has no page (make book writes it)`);
    process.exit(1);
}
const browser = await launch(chromium);
try {
    const page = await browser.newPage();
    let current = '';
    const complain = (what) => problems.push(`${current}: ${what}`);
    page.on('Runtime.exceptionThrown', (p) => complain(`script error: ${p.exceptionDetails.exception?.description || p.exceptionDetails.text}`));
    page.on('Runtime.consoleAPICalled', (p) => {
        if (p.type === 'error' || p.type === 'assert') complain(`console error: ${p.args.map((a) => a.value ?? a.description).join(' ')}`);
    });
    page.on('Log.entryAdded', (p) => {
        if (p.entry.level === 'error') complain(`console error: ${p.entry.text}${p.entry.url ? ` (${p.entry.url})` : ''}`);
    });
    const viewport = (v) => page.send('Emulation.setDeviceMetricsOverride', { ...v, deviceScaleFactor: 1, mobile: v === PHONE });
    const shoot = async (name) => {
        const { data } = await page.send('Page.captureScreenshot', { format: 'png' });
        writeFileSync(join(shots, name), Buffer.from(data, 'base64'));
    };
    mkdirSync(shots, { recursive: true });
    for (const file of files) {
        current = relative(root, file);
        await viewport(DESKTOP);
        await page.goto(pathToFileURL(file).href);
        const seen = await page.evaluate(INSPECT);
        equations += seen.equations;
        images += seen.images.length;
        for (const i of seen.images) if (!i.complete || i.width === 0) complain(`the image ${i.src} does not load`);
        for (const m of seen.unrendered) complain(`an equation not typeset: ${m}`);
        for (const e of seen.errors) complain(`an equation KaTeX cannot typeset: ${e}`);
        for (const r of seen.raw) complain(`raw TeX in the text: ${r}`);
        if (/^\d\d_[^/-]*\.html$/.test(current) && seen.equations === 0) complain('a chapter without a typeset equation');
        ids.set(file, new Set(seen.ids));
        for (const href of seen.links) links.push([current, href]);
        const shot = SHOT_PAGES.includes(current) && current.replace(/\.html$/, '');
        if (shot) await shoot(`${shot}-desktop.png`);
        if (shot && shot !== 'index') {
            await page.evaluate(`document.querySelector('.katex-display')?.scrollIntoView({ block: 'center' })`);
            await shoot(`${shot}-equation-desktop.png`);
        }
        await viewport(PHONE);
        await page.evaluate('window.scrollTo(0, 0)');
        const width = await page.evaluate(WIDTH);
        if (width > PHONE.width) complain(`${width} pixels wide in a window of ${PHONE.width}`);
        if (shot) await shoot(`${shot}-phone.png`);
        if (shot && shot !== 'index') {
            await page.evaluate(`document.querySelector('.katex-display')?.scrollIntoView({ block: 'center' })`);
            await shoot(`${shot}-equation-phone.png`);
        }
    }
} finally {
    await browser.close();
}

// The links: a file of the book that exists, and an anchor its page has.
let internal = 0, anchors = 0, within = 0, outside = 0;
for (const [from, href] of links) {
    const url = new URL(href);
    if (url.protocol !== 'file:') { outside++; continue; }
    internal++;
    const target = fileURLToPath(url);
    if (target === join(root, from)) within++;
    if (!target.startsWith(root + '/') || !existsSync(target)) {
        problems.push(`${from}: the link ${href} leads nowhere`);
        continue;
    }
    if (url.hash && target.endsWith('.html')) {
        anchors++;
        const id = decodeURIComponent(url.hash.slice(1));
        if (!ids.get(target)?.has(id)) problems.push(`${from}: the anchor ${url.hash} is not in ${relative(root, target)}`);
    }
}

const seconds = ((Date.now() - started) / 1000).toFixed(1);
for (const p of problems) console.error(`check-book: ${p}`);
console.log(`check-book: ${files.length} pages, ${equations} equations, ${images} images, ${internal} links (${internal - within} to ` +
    `another page or file, ${within} within the page; ${anchors} to an anchor; ` +
    `${outside} out of the book, not followed) at ${DESKTOP.width} and ${PHONE.width} pixels wide in ${seconds} s: ` +
    `${problems.length ? `${problems.length} problems` : 'no problem'}; screenshots in ${shots}`);
process.exit(problems.length ? 1 : 0);
