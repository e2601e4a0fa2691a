// What the browser tests share: a static server of web/ (as any host serves it) and headless
// Chromium with software WebGL (SwiftShader), driven by puppeteer-core (which downloads no
// browser: CHROMIUM, else /usr/bin/chromium).
import http from 'node:http';
import fs from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';

export const WEB = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.wasm': 'application/wasm', '.json': 'application/json' };

/** Serves web/ on a free port of 127.0.0.1; resolves to { url, close }. */
export async function serve() {
  const server = http.createServer(async (req, res) => {
    const url = new URL(req.url, 'http://localhost');
    const file = path.join(WEB, decodeURIComponent(url.pathname === '/' ? '/index.html' : url.pathname));
    if (!file.startsWith(WEB)) {
      res.writeHead(403).end();
      return;
    }
    try {
      const body = await fs.readFile(file);
      res.writeHead(200, { 'content-type': TYPES[path.extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404).end('not found');
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  return { url: `http://127.0.0.1:${port}/`, close: () => server.close() };
}

/** Headless Chromium with WebGL on the CPU. */
export async function browser() {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
      '--window-size=1000,700'],
    defaultViewport: { width: 1000, height: 700 },
  });
}

/** Opens the page at `query`, its console errors collected; waits until it is ready. */
export async function open(browser, url, query) {
  const page = await browser.newPage();
  const console = [];
  page.on('console', (m) => {
    if (m.type() === 'error') console.push(m.text());
  });
  page.on('pageerror', (e) => console.push(String(e)));
  await page.goto(`${url}${query}`);
  await page.waitForFunction(() => window.app && window.app.ready, { timeout: 60_000 });
  return { page, console };
}

export function check(condition, message) {
  if (!condition) throw new Error(message);
  console.log(`ok: ${message}`);
}
