"""A small Chrome DevTools Protocol client for headless Chromium, Python's standard library only.

Chromium is started with --remote-debugging-pipe: it reads commands from its fd 3 and writes
replies and events to its fd 4, each a JSON object ended by a NUL byte. No port, no websocket.

    with Browser() as b:
        page = b.open('file:///.../ch01.html')
        page.wait_for('window.raybookLive && window.raybookLive.panels.length > 0', 30)
        r = page.evaluate('window.raybookLive.panels[0].render({size: "160x120"})', 120)
        page.screenshot('/tmp/x.png')

Used by tests/web/live_panel.py and tests/perf/web/bench_live.py.
"""
import base64
import json
import os
import shutil
import subprocess
import tempfile
import time


def find_chromium():
    for name in ('chromium', 'chromium-browser', 'google-chrome'):
        path = shutil.which(name)
        if path:
            return path
    return None


class CdpError(Exception):
    pass


class Browser:
    def __init__(self, chromium=None, width=1100, height=900, extra_args=()):
        self.chromium = chromium or find_chromium()
        if not self.chromium:
            raise CdpError('no chromium on PATH (Debian: apt-get install chromium)')
        self.profile = tempfile.mkdtemp(prefix='rb-chromium-')
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        # Chromium expects the pipe on fds 3 and 4 exactly. In the child, each end moves out
        # of the way first (either may be fd 3 or 4 already), then into place; close_fds would
        # close them again after preexec_fn, so it is off (os.pipe's fds are close-on-exec).
        def child_fds():
            a = os.dup(to_chrome_r)
            b = os.dup(from_chrome_w)
            os.dup2(a, 3)
            os.dup2(b, 4)
        args = [self.chromium, '--headless', '--no-sandbox', '--disable-gpu',
                '--remote-debugging-pipe', '--user-data-dir=' + self.profile,
                '--no-first-run', '--no-default-browser-check', '--disable-extensions',
                '--force-color-profile=srgb', '--window-size=%d,%d' % (width, height),
                *extra_args, 'about:blank']
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL, preexec_fn=child_fds,
                                     close_fds=False)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buf = b''
        self.next_id = 1
        self.events = []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        try:
            self.send('Browser.close', timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        for fd in (self.to_chrome, self.from_chrome):
            try:
                os.close(fd)
            except OSError:
                pass
        shutil.rmtree(self.profile, ignore_errors=True)

    def _read_message(self, deadline):
        import select
        while b'\0' not in self.buf:
            left = deadline - time.time()
            if left <= 0:
                raise CdpError('no answer from chromium in time')
            ready, _, _ = select.select([self.from_chrome], [], [], min(left, 1.0))
            if ready:
                chunk = os.read(self.from_chrome, 1 << 20)
                if not chunk:
                    raise CdpError('chromium closed the pipe (exit code %s)' % self.proc.poll())
                self.buf += chunk
        msg, self.buf = self.buf.split(b'\0', 1)
        return json.loads(msg)

    def send(self, method, params=None, session=None, timeout=60):
        mid = self.next_id
        self.next_id += 1
        msg = {'id': mid, 'method': method, 'params': params or {}}
        if session:
            msg['sessionId'] = session
        os.write(self.to_chrome, json.dumps(msg).encode() + b'\0')
        deadline = time.time() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get('id') == mid:
                if 'error' in reply:
                    raise CdpError('%s: %s' % (method, reply['error']))
                return reply.get('result', {})
            self.events.append(reply)

    def open(self, url, timeout=60):
        target = self.send('Target.createTarget', {'url': 'about:blank'})['targetId']
        session = self.send('Target.attachToTarget', {'targetId': target, 'flatten': True})['sessionId']
        page = Page(self, session)
        page.send('Runtime.enable')
        page.send('Page.enable')
        page.send('Page.navigate', {'url': url}, timeout=timeout)
        page.wait_for('document.readyState === "complete"', timeout)
        return page


class Page:
    def __init__(self, browser, session):
        self.browser = browser
        self.session = session

    def send(self, method, params=None, timeout=60):
        return self.browser.send(method, params, self.session, timeout)

    def evaluate(self, expression, timeout=60):
        """The value of EXPRESSION (awaited if it is a promise), as JSON."""
        r = self.send('Runtime.evaluate', {'expression': expression, 'awaitPromise': True,
                                           'returnByValue': True, 'timeout': timeout * 1000},
                      timeout=timeout + 5)
        if 'exceptionDetails' in r:
            d = r['exceptionDetails']
            text = d.get('exception', {}).get('description') or d.get('text')
            raise CdpError('page: %s' % text)
        return r['result'].get('value')

    def wait_for(self, expression, timeout=60, poll=0.1):
        deadline = time.time() + timeout
        while True:
            try:
                if self.evaluate('!!(%s)' % expression, timeout=10):
                    return
            except CdpError:
                pass
            if time.time() > deadline:
                raise CdpError('timed out after %g s waiting for %s' % (timeout, expression))
            time.sleep(poll)

    def console_messages(self):
        out = []
        for e in self.browser.events:
            if e.get('sessionId') != self.session:
                continue
            if e.get('method') == 'Runtime.consoleAPICalled':
                out.append(' '.join(str(a.get('value', a.get('description', '')))
                                    for a in e['params'].get('args', [])))
            elif e.get('method') == 'Runtime.exceptionThrown':
                d = e['params']['exceptionDetails']
                out.append('exception: ' + (d.get('exception', {}).get('description') or d.get('text', '')))
        return out

    def screenshot(self, path, full_page=True):
        params = {'format': 'png'}
        if full_page:
            params['captureBeyondViewport'] = True
        data = self.send('Page.captureScreenshot', params)['data']
        with open(path, 'wb') as f:
            f.write(base64.b64decode(data))
