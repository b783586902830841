#!/usr/bin/env python3
"""Drives the kappa page (web/, docs/web.md) in headless Chromium, for the
tests (tests/test_web_page.cpp) and the budgets (scripts/web-budgets.sh).

    page_driver.py SITE MESHES OUT ACTION...

SITE is the folder scripts/build-web.sh made, MESHES a folder of meshes; both
are served on localhost (the meshes under meshes/). Each ACTION writes into
OUT and prints one line "NAME: ..." with what it saw:

    shot:NAME:QUERY      opens index.html?QUERY, waits for "kappa: ready", saves
                         the canvas as NAME.png (the page's own PNG download)
    svg:NAME:QUERY       the same, then the page's SVG download as NAME.svg
    error:NAME:QUERY:NEXT opens QUERY, which must fail: writes the title and the
                         message shown to NAME.txt; then opens the mesh file NEXT
                         (local paths, several separated by commas: a .gltf and
                         its .bin) through the page's file picker and saves
                         NAME.png once it is drawn
    drop:NAME:QUERY:FILES opens QUERY, then drops FILES (local paths separated by
                         commas) on the page and saves NAME.png once drawn
    page:NAME:QUERY      the same, saving a screenshot of the whole 1100x640 page (the panel too)
    time:NAME:QUERY      seconds from navigation to "kappa: ready"
    orbit:NAME:QUERY:N   then N drag steps of orbiting; frames a second
    zoom:NAME:QUERY:N    then N wheel clicks in, and once the view's fields are
                         prepared (in slices) N clicks out: writes NAME.json
                         with the opening's and each zoom's preparation's
                         slices (the page's times.preparations) and the
                         longest main-thread tasks
                         seen meanwhile (PerformanceObserver 'longtask', over 50
                         ms), and NAME.png once the view is drawn back out

Chromium is driven over the DevTools protocol on a pipe
(--remote-debugging-pipe: file descriptors 3 and 4), which needs nothing
beyond the Python standard library. WebGL2 comes from SwiftShader.
"""
import base64
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time


class Browser:
    def __init__(self):
        chromium = shutil.which('chromium') or shutil.which('chromium-browser')
        if not chromium:
            raise SystemExit('page_driver: chromium not found')
        self.profile = tempfile.mkdtemp(prefix='kappa-chromium-')
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()

        def pipes_at_3_and_4():
            os.dup2(to_browser_r, 3)
            os.dup2(from_browser_w, 4)

        self.process = subprocess.Popen(
            [chromium, '--headless=new', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
             '--remote-debugging-pipe', '--no-first-run', '--no-default-browser-check', '--disable-gpu-sandbox',
             '--hide-scrollbars', '--mute-audio', '--user-data-dir=' + self.profile]
            + os.environ.get('KAPPA_CHROMIUM_FLAGS', '').split() + ['about:blank'],
            close_fds=False, preexec_fn=pipes_at_3_and_4,  # (pass_fds would close 3 and 4 after the dup2)
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.buffer = b''
        self.next_id = 0
        target = self.call('Target.createTarget', {'url': 'about:blank'})['targetId']
        self.session = self.call('Target.attachToTarget', {'targetId': target, 'flatten': True})['sessionId']
        self.call('Page.enable', session=True)
        self.call('Runtime.enable', session=True)
        self.call('Emulation.setDeviceMetricsOverride', {'width': 1100, 'height': 640, 'deviceScaleFactor': 1,
                                                         'mobile': False}, session=True)

    def call(self, method, params=None, session=False, timeout=120):
        self.next_id += 1
        message = {'id': self.next_id, 'method': method, 'params': params or {}}
        if session:
            message['sessionId'] = self.session
        os.write(self.to_browser, json.dumps(message).encode() + b'\0')
        deadline = time.time() + timeout
        while time.time() < deadline:
            while b'\0' not in self.buffer:
                chunk = os.read(self.from_browser, 1 << 20)
                if not chunk:
                    raise RuntimeError('chromium closed the DevTools pipe')
                self.buffer += chunk
            raw, self.buffer = self.buffer.split(b'\0', 1)
            reply = json.loads(raw)
            if reply.get('id') == self.next_id:
                if 'error' in reply:
                    raise RuntimeError(method + ': ' + reply['error'].get('message', ''))
                return reply.get('result', {})
        raise RuntimeError(method + ': no reply')

    def evaluate(self, expression, timeout=120):
        result = self.call('Runtime.evaluate', {'expression': expression, 'awaitPromise': True,
                                                'returnByValue': True}, session=True, timeout=timeout)
        if 'exceptionDetails' in result:
            raise RuntimeError(expression + ': ' + json.dumps(result['exceptionDetails'])[:500])
        return result['result'].get('value')

    def navigate(self, url):
        self.call('Page.navigate', {'url': url}, session=True)

    def wait_title(self, done, timeout=120):
        deadline = time.time() + timeout
        title = ''
        while time.time() < deadline:
            title = self.evaluate('document.title') or ''
            if done(title):
                return title
            time.sleep(0.02)
        raise RuntimeError('the page title is still %r after %d s' % (title, timeout))

    def cpu_seconds(self):
        """CPU time (user + system) used so far by Chromium's processes (the browser and its children)."""
        tick = os.sysconf('SC_CLK_TCK')
        parents, times = {}, {}
        for pid in os.listdir('/proc'):
            if not pid.isdigit():
                continue
            try:
                with open('/proc/%s/stat' % pid) as f:
                    fields = f.read().rsplit(')', 1)[1].split()
            except OSError:
                continue
            parents[int(pid)] = int(fields[1])
            times[int(pid)] = (int(fields[11]) + int(fields[12])) / tick
        def in_tree(pid):
            while pid > 1:
                if pid == self.process.pid:
                    return True
                pid = parents.get(pid, 0)
            return False
        return sum(t for pid, t in times.items() if in_tree(pid))

    def close(self):
        try:
            self.call('Browser.close', timeout=10)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, '.wasm': 'application/wasm',
                      '.js': 'text/javascript'}

    def log_message(self, *args):
        pass


def serve(site, meshes):
    """Serves SITE with MESHES under meshes/ on a free localhost port; returns the base URL."""
    root = tempfile.mkdtemp(prefix='kappa-site-')
    for name in os.listdir(site):
        os.symlink(os.path.abspath(os.path.join(site, name)), os.path.join(root, name))
    os.symlink(os.path.abspath(meshes), os.path.join(root, 'meshes'))
    server = http.server.ThreadingHTTPServer(('127.0.0.1', 0), functools.partial(QuietHandler, directory=root))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return 'http://127.0.0.1:%d/' % server.server_address[1]


def is_settled(title):
    return title == 'kappa: ready' or title.startswith('kappa: error')


def save_data_url(url, path):
    with open(path, 'wb') as f:
        f.write(base64.b64decode(url.split(',', 1)[1]))


def local_files(name, paths):
    files = [os.path.abspath(f) for f in paths.split(',')]
    for f in files:
        if not os.path.isfile(f):
            raise RuntimeError(name + ': no file ' + f)
    return files


# Files ([{name, data (base64)}]) dropped on the page; the title says
# "kappa: dropping" until the page has opened them.
DROP_SCRIPT = '''(() => {
    document.title = 'kappa: dropping';
    const files = %s, transfer = new DataTransfer();
    for (const f of files)
        transfer.items.add(new File([Uint8Array.from(atob(f.data), c => c.charCodeAt(0))], f.name));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
})()'''


def run(browser, base, out, action):
    kind, name, rest = action.split(':', 2)
    if kind in ('error', 'drop'):
        query, next_mesh = rest.rsplit(':', 1)
    elif kind in ('orbit', 'zoom'):
        query, steps = rest.rsplit(':', 1)
    else:
        query = rest
    start = time.time()
    browser.navigate(base + 'index.html?' + query)
    title = browser.wait_title(is_settled)
    seconds = time.time() - start
    if kind == 'error':
        if title == 'kappa: ready':
            raise RuntimeError(name + ': the page opened ' + query + ' without an error')
        shown = browser.evaluate("document.getElementById('message').textContent")
        with open(os.path.join(out, name + '.txt'), 'w') as f:
            f.write(title + '\n' + shown + '\n')
        files = local_files(name, next_mesh)
        # As a person picks files: the file input's files set, its change event fired.
        document = browser.call('DOM.getDocument', session=True)['root']['nodeId']
        picker = browser.call('DOM.querySelector', {'nodeId': document, 'selector': '#file'}, session=True)
        browser.call('DOM.setFileInputFiles', {'files': files, 'nodeId': picker['nodeId']}, session=True)
        error_title = title
        title = browser.wait_title(lambda t: t != error_title)
        title = browser.wait_title(is_settled)
    if kind == 'drop':
        # As a person drops files: a drop event whose DataTransfer holds them.
        dropped = [{'name': os.path.basename(f), 'data': base64.b64encode(open(f, 'rb').read()).decode()}
                   for f in local_files(name, next_mesh)]
        browser.evaluate(DROP_SCRIPT % json.dumps(dropped))
        title = browser.wait_title(is_settled)
    if title != 'kappa: ready':
        raise RuntimeError(name + ': ' + title)
    if kind == 'page':
        shot = browser.call('Page.captureScreenshot', {'format': 'png'}, session=True)
        with open(os.path.join(out, name + '.png'), 'wb') as f:
            f.write(base64.b64decode(shot['data']))
    if kind in ('shot', 'svg', 'error', 'drop'):
        save_data_url(browser.evaluate('kappaPage.pngDataUrl()'), os.path.join(out, name + '.png'))
    if kind == 'svg':
        with open(os.path.join(out, name + '.svg'), 'w') as f:
            f.write(browser.evaluate('kappaPage.svgText()'))
    if kind == 'time':
        times = browser.evaluate('JSON.stringify(kappaPage.times)')
        print('%s: ready %.2f s after navigation (in the page, seconds: %s)' % (name, seconds, times))
    elif kind == 'orbit':
        # Drags as a person orbits: a pointer event a step, each drawn before the next.
        cpu_before = browser.cpu_seconds()
        frames = browser.evaluate('''(async () => {
            const c = document.getElementById('canvas'), r = c.getBoundingClientRect();
            const at = (x, y, type) => c.dispatchEvent(new PointerEvent(type, {clientX: r.left + x,
                clientY: r.top + y, button: 0, pointerId: 1, bubbles: true}));
            const frame = () => new Promise(done => requestAnimationFrame(() => setTimeout(done, 0)));
            const x0 = r.width / 2, y0 = r.height / 2;
            at(x0, y0, 'pointerdown');
            await frame();
            const t0 = performance.now();
            let drawing = 0;
            for (let i = 1; i <= %d; ++i) {
                at(x0 + 4 * i, y0, 'pointermove');
                await frame();
                drawing += kappaPage.times.draw;
            }
            const seconds = (performance.now() - t0) / 1000;
            at(x0 + 4 * %d, y0, 'pointerup');
            return [%d / seconds, 1000 * drawing / %d];
        })()''' % (int(steps), int(steps), int(steps), int(steps)), timeout=300)
        cpu = browser.cpu_seconds() - cpu_before
        print('%s: %.1f frames a second over %s drag steps (kappa_draw %.0f ms a frame; Chromium used %.0f ms '
              'of CPU a frame)' % (name, frames[0], steps, frames[1], 1000 * cpu / int(steps)))
    elif kind == 'zoom':
        phases = browser.evaluate(ZOOM_SCRIPT % int(steps), timeout=300)
        with open(os.path.join(out, name + '.json'), 'w') as f:
            json.dump(phases, f)
        save_data_url(browser.evaluate('kappaPage.pngDataUrl()'), os.path.join(out, name + '.png'))
        for phase in phases:
            p = phase['preparation']
            print('%s: zoom %s: fields prepared in %d slices, the longest %.0f ms, %.0f ms of work in %.0f ms; '
                  'longest main-thread task %.0f ms, last draw %.0f ms' % (name, phase['zoom'], p['slices'], p['longest_ms'],
                                                        p['work_ms'], p['wall_ms'], phase['longest_task_ms'], phase['last_draw_ms']))
    else:
        print('%s: %s (%.2f s)' % (name, title, seconds))


# Wheel clicks at the canvas's centre, N in then N out; after each burst, waits
# until the page has prepared the fields of the view at rest. Returns, per
# burst, the page's record of that preparation and the longest task seen.
ZOOM_SCRIPT = '''(async () => {
    const c = document.getElementById('canvas'), r = c.getBoundingClientRect();
    const frame = () => new Promise(done => requestAnimationFrame(() => setTimeout(done, 0)));
    const sleep = ms => new Promise(done => setTimeout(done, ms));
    let longest = 0;
    new PerformanceObserver(list => {
        for (const e of list.getEntries()) longest = Math.max(longest, e.duration);
    }).observe({ entryTypes: ['longtask'] });
    // The first preparation: opening the mesh (in steps) and its first view's fields.
    const phases = [{ zoom: 'open', preparation: kappaPage.times.preparations[0], last_draw_ms: 0,
                      longest_task_ms: 0 }];
    for (const dir of ['in', 'out']) {
        const before = kappaPage.times.preparations.length;
        for (let i = 0; i < %d; ++i) {
            c.dispatchEvent(new WheelEvent('wheel', { clientX: r.left + r.width / 2, clientY: r.top + r.height / 2,
                                                      deltaY: dir === 'in' ? -100 : 100, bubbles: true,
                                                      cancelable: true }));
            await frame();
        }
        longest = 0;
        const deadline = performance.now() + 120000;
        while (kappaPage.times.preparations.length === before || kappaPage.preparing()) {
            if (performance.now() > deadline) throw new Error('the fields of the view were not prepared');
            await sleep(20);
        }
        await sleep(100);  // the last long tasks reported
        phases.push({ zoom: dir, preparation: kappaPage.times.preparations[before], last_draw_ms: 1000 * kappaPage.times.draw,
                      longest_task_ms: longest });
    }
    return phases;
})()'''


def main(argv):
    if len(argv) < 5:
        print(__doc__)
        return 2
    site, meshes, out = argv[1:4]
    os.makedirs(out, exist_ok=True)
    base = serve(site, meshes)
    browser = Browser()
    try:
        for action in argv[4:]:
            run(browser, base, out, action)
    finally:
        browser.close()
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
