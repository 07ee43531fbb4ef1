// cdp.mjs - headless Chromium driven over its DevTools protocol on a pipe
// (--remote-debugging-pipe: commands on the browser's fd 3, answers and
// events on its fd 4, each a JSON message ended by a NUL byte), so that no
// network port and no package beyond Debian's chromium and nodejs is needed.
//
//     const browser = await launch('/usr/bin/chromium');
//     const page = await browser.newPage();      // a tab
//     await page.goto('file:///...');             // resolves on its load event
//     await page.send('Runtime.evaluate', {...}); // any command of the tab
//     page.on('Runtime.exceptionThrown', f);      // any event of the tab
//     await browser.close();
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const COMMAND_TIMEOUT_MS = 60000;

export async function launch(executable) {
    const profile = mkdtempSync(join(tmpdir(), 'book-chromium-'));
    const child = spawn(executable, [
        '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
        '--disable-component-update', '--disable-sync', '--no-first-run', '--no-default-browser-check',
        '--disable-extensions', '--hide-scrollbars', '--mute-audio', `--user-data-dir=${profile}`,
        '--remote-debugging-pipe', 'about:blank',
    ], { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (d) => { stderr = (stderr + d).slice(-4000); });
    const toBrowser = child.stdio[3], fromBrowser = child.stdio[4];
    let nextId = 1, buffered = '';
    const pending = new Map(), listeners = new Map();
    let exited = null;
    const failAll = (why) => {
        for (const { reject } of pending.values()) reject(new Error(why));
        pending.clear();
    };
    child.on('exit', (code, signal) => {
        exited = `chromium exited (${signal || code})` + (stderr ? `: ${stderr.trim().split('\n').slice(-3).join(' | ')}` : '');
        failAll(exited);
    });
    child.on('error', (e) => { exited = `cannot run ${executable}: ${e.message}`; failAll(exited); });
    fromBrowser.on('data', (chunk) => {
        buffered += chunk.toString('utf8');
        let end;
        while ((end = buffered.indexOf('\0')) >= 0) {
            const message = JSON.parse(buffered.slice(0, end));
            buffered = buffered.slice(end + 1);
            if (message.id !== undefined && pending.has(message.id)) {
                const { resolve, reject, method } = pending.get(message.id);
                pending.delete(message.id);
                if (message.error) reject(new Error(`${method}: ${message.error.message}`));
                else resolve(message.result);
            } else if (message.method) {
                for (const f of listeners.get(`${message.sessionId || ''} ${message.method}`) || []) f(message.params);
            }
        }
    });

    function send(method, params = {}, sessionId = undefined) {
        if (exited) return Promise.reject(new Error(exited));
        const id = nextId++;
        return new Promise((resolve, reject) => {
            const timer = setTimeout(() => {
                pending.delete(id);
                reject(new Error(`${method}: no answer from chromium in ${COMMAND_TIMEOUT_MS / 1000} s`));
            }, COMMAND_TIMEOUT_MS);
            pending.set(id, {
                method,
                resolve: (r) => { clearTimeout(timer); resolve(r); },
                reject: (e) => { clearTimeout(timer); reject(e); },
            });
            toBrowser.write(JSON.stringify({ id, method, params, ...(sessionId ? { sessionId } : {}) }) + '\0');
        });
    }
    function on(sessionId, event, f) {
        const key = `${sessionId || ''} ${event}`;
        if (!listeners.has(key)) listeners.set(key, []);
        listeners.get(key).push(f);
    }

    async function newPage() {
        const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
        const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
        const page = {
            send: (method, params) => send(method, params, sessionId),
            on: (event, f) => on(sessionId, event, f),
            async goto(url) {
                const loaded = new Promise((resolve) => {
                    const f = () => { resolve(); };
                    page.once('Page.loadEventFired', f);
                });
                const { errorText } = await page.send('Page.navigate', { url });
                if (errorText) throw new Error(`${url}: ${errorText}`);
                await loaded;
            },
            once(event, f) {
                let done = false;
                on(sessionId, event, (p) => { if (!done) { done = true; f(p); } });
            },
            async evaluate(expression) {
                const r = await page.send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true });
                if (r.exceptionDetails) throw new Error(`evaluating in the page: ${r.exceptionDetails.exception?.description || r.exceptionDetails.text}`);
                return r.result.value;
            },
        };
        await page.send('Page.enable');
        await page.send('Runtime.enable');
        await page.send('Log.enable');
        return page;
    }

    async function close() {
        if (!exited) {
            try { await send('Browser.close'); } catch { /* it is closing */ }
        }
        await new Promise((resolve) => (exited ? resolve() : child.on('exit', resolve)));
        rmSync(profile, { recursive: true, force: true });
    }

    await send('Browser.getVersion'); // the pipe works
    return { newPage, close };
}
