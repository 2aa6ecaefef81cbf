#!/usr/bin/env python3
"""live_panel: the docs' live chapter panels render what the command line renders.

    live_panel.py --rt build/rt_ch17 --html docs/html --work build/live_panel [--chapters 1,5,13|all]

In headless Chromium (Debian's chromium, driven over the DevTools pipe, tests/web/cdp.py), for
each chapter N given it opens the built page docs/html/chNN.html from file://, renders the
chapter's scene in the page's panel at 160x120 and requires the canvas to equal native rt's
render of the same scene (./rt --features=<the panel's> --size 160x120 --threads 1), pixel for
pixel: rt --compare must report a largest difference of 0, and the first differing pixels are
listed if not. Then, on chapter 1's page:
  - the same render from a plain static server (http.server) gives the same pixels;
  - a broken call in the text box shows the command line's message, file:line included;
  - `while true do end` stops with the command line's "ran more than ... Lua instructions"
    message, while the page keeps answering;
  - Stop ends a running render at once, and the next render works;
  - the page opened with ?rb-autorender=160x120 renders on load and leaves the command line's
    picture in <pre id="rb-autorender-result">.
And on chapter 18's page (issue 38), a render long enough for previews (its Cornell box at
80x60 with 144 samples a pixel, raised from 64 in the text box, some seconds in the page) shows at
least two previews before the picture, a quarter-size one and then full-size ones of growing
sample counts, and the picture that follows them equals native rt's.
With --bad-input (as CTest runs it), every case of tests/bad_input/cases that the panel can
run must fail in the page with native rt's message (see bad_input below).
Exit code 0 when all pass, 1 otherwise, 77 (skipped) when there is no bundle or no chromium.
"""
import argparse
import base64
import functools
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import cdp  # noqa: E402
import png_read  # noqa: E402  (tests/png_read.py)

SIZE = '160x120'
failures = []


def check(ok, what, detail=''):
    print('%s: %s%s' % ('ok  ' if ok else 'FAIL', what, ('\n      ' + detail.replace('\n', '\n      ')) if detail and not ok else ''))
    sys.stdout.flush()
    if not ok:
        failures.append(what)
    return ok


def png_pixels(path):
    """(width, height, rows of RGB tuples) of an 8-bit PNG, read by tests/png_read.py."""
    w, h, channels, rows = png_read.read_png(path)
    return w, h, [[tuple(row[x * channels:x * channels + 3]) for x in range(w)] for row in rows]


def differing_pixels(a, b, most=10):
    wa, ha, ra = png_pixels(a)
    wb, hb, rb = png_pixels(b)
    if (wa, ha) != (wb, hb):
        return ['sizes differ: %dx%d against %dx%d' % (wa, ha, wb, hb)]
    out, count = [], 0
    for y in range(ha):
        for x in range(wa):
            if ra[y][x] != rb[y][x]:
                count += 1
                if len(out) < most:
                    out.append('(%d, %d): page %s, native %s' % (x, y, ra[y][x], rb[y][x]))
    return ['%d pixel(s) differ' % count] + out


def native(rt, features, scene, out, size=SIZE):
    args = [rt, '--features=' + features, '--size', size, '--threads', '1', '--output', out, scene]
    t0 = time.time()
    r = subprocess.run(args, capture_output=True, text=True)
    return r, time.time() - t0


def save_canvas(result, path):
    with open(path, 'wb') as f:
        f.write(base64.b64decode(result['pixels'].split(',', 1)[1]))


def open_panel(browser, url):
    page = browser.open(url)
    page.wait_for('window.raybookLive && window.raybookLive.panels.length > 0', 30)
    page.wait_for('window.raybookLive.panels[0].features || /did not start/.test('
                  'document.querySelector(".rb-live .rb-switches").textContent)', 180)
    check(page.evaluate('!!window.raybookLive.panels[0].features'), 'rt starts in the page: ' + url,
          page.evaluate('document.querySelector(".rb-live").innerText') + '\n' +
          '\n'.join(page.console_messages()))
    return page


def render(page, opts, timeout):
    expr = 'window.raybookLive.panels[0].render(%s)' % (opts,)
    return page.evaluate(expr, timeout)


def terminal(text):
    """TEXT as a terminal leaves it: what follows each line's last carriage return (rt's
    WebAssembly build draws its progress bar on stderr, which natively goes to a pipe here)."""
    return '\n'.join(l[l.rfind('\r') + 1:] for l in text.split('\n'))


def panel_text(page):
    return page.evaluate('document.querySelector(".rb-live pre.rb-msg").textContent')


def compare_chapter(page, args, n, scene_name, label, text=None, size=SIZE):
    opts = '{size: "%s"%s}' % (size, '' if text is None else ', text: ' + json_str(text))
    r = render(page, opts, args.timeout)
    return r if same_as_native(args, r, n, scene_name, label, text, size) else None


def same_as_native(args, r, n, scene_name, label, text=None, size=SIZE):
    """Whether the panel's render R of SCENE_NAME (or of TEXT typed in its place) succeeded and
    its canvas equals native rt's render, pixel for pixel."""
    if not check(r and r['code'] == 0 and r['pixels'], '%s: the panel renders %s' % (label, scene_name),
                 repr({k: v for k, v in (r or {}).items() if k not in ('pixels', 'frames')})):
        return False
    canvas = os.path.join(args.work, 'ch%02d-%s-page.png' % (n, re.sub(r'[^a-z]+', '-', label)))
    save_canvas(r, canvas)
    features = r['args'][0].split('=', 1)[1]
    ref = os.path.join(args.work, 'ch%02d-%s-native.png' % (n, re.sub(r'[^a-z]+', '-', label)))
    scene = os.path.join(args.scenes, scene_name)
    if text is not None and text != open(scene).read():  # an edited scene (with no assets)
        scene = os.path.join(args.work, scene_name)
        with open(scene, 'w') as f:
            f.write(text)
    nat, secs = native(args.rt, features, scene, ref, size)
    if not check(nat.returncode == 0, 'native rt renders ' + scene_name, nat.stderr):
        return False
    cmp = subprocess.run([args.rt, '--compare', canvas, ref], capture_output=True, text=True)
    largest = re.search(r'largest\s+(\S+)', cmp.stdout)
    same = largest is not None and float(largest.group(1)) == 0
    detail = cmp.stdout + cmp.stderr
    if not same:
        try:
            detail += '\n' + '\n'.join(differing_pixels(canvas, ref))
        except Exception as e:  # an unexpected PNG kind: --compare's numbers still stand
            detail += '\n(could not list the pixels: %s)' % e
    return check(same, '%s: chapter %d\'s canvas equals native rt (--features=%s, %s): page %.2f s, '
                 'native %.2f s' % (label, n, features, size, r['ms'] / 1000, secs), detail)


def serve(root):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass
    handler = functools.partial(Quiet, directory=root)
    server = http.server.ThreadingHTTPServer(('127.0.0.1', 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--rt', required=True, help='native rt with every chapter (rt_ch17)')
    ap.add_argument('--html', required=True, help='the built docs (docs/html)')
    ap.add_argument('--work', required=True, help='a folder for the images')
    ap.add_argument('--scenes', default=os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scenes'))
    ap.add_argument('--chapters', default='1,5,13', help='N,N,... or all (every page with a panel)')
    ap.add_argument('--timeout', type=float, default=300, help='seconds for one render')
    ap.add_argument('--skip-limits', action='store_true', help='only the pixel comparisons')
    ap.add_argument('--bad-input', action='store_true',
                    help='also run tests/bad_input/cases in the page and compare the messages')
    args = ap.parse_args()
    args.rt = os.path.abspath(args.rt)
    args.html = os.path.abspath(args.html)
    args.scenes = os.path.abspath(args.scenes)
    os.makedirs(args.work, exist_ok=True)

    bundle = os.path.join(args.html, 'live', 'raybook-live.js')
    if not os.path.exists(bundle):
        print('live_panel: no %s (make docs builds it when emscripten is installed); skipped' % bundle)
        return 77
    if not cdp.find_chromium():
        print('live_panel: no chromium (Debian: apt-get install chromium); skipped')
        return 77
    print('live_panel: bundle %s, %.1f MiB' % (bundle, os.path.getsize(bundle) / 2**20))

    scenes = {}
    for name in os.listdir(args.scenes):
        m = re.fullmatch(r'chapter(\d\d)-.*\.lua', name)
        if m:
            scenes[int(m.group(1))] = name
    if args.chapters == 'all':  # every chapter whose built page has a panel
        chapters = [n for n in sorted(scenes) if os.path.exists(os.path.join(args.html, 'ch%02d.html' % n))
                    and 'rb-live' in open(os.path.join(args.html, 'ch%02d.html' % n)).read()]
    else:
        chapters = [int(c) for c in args.chapters.split(',')]

    with cdp.Browser() as browser:
        for n in chapters:
            url = 'file://%s/ch%02d.html' % (args.html, n)
            page = open_panel(browser, url)
            if not page.evaluate('!!window.raybookLive.panels[0].features'):
                continue
            compare_chapter(page, args, n, scenes[n], 'file://')
            # The chapter's own switch off: rt --features=all,-NAME, as on the command line.
            name = page.evaluate('(window.raybookLive.panels[0].features.find(f => f.chapter === %d && !f.core) || {}).name || ""' % n)
            if name:
                page.evaluate('(() => { const b = [...document.querySelectorAll(".rb-live input[type=checkbox]")].find(b => b.value === "%s"); b.click(); return b.checked; })()' % name)
                r = compare_chapter(page, args, n, scenes[n], 'file:// -' + name)
                check(r is not None and r['args'][0] == '--features=all,-' + name,
                      'unchecking chapter %d\'s switch renders with --features=all,-%s' % (n, name),
                      repr(r and r['args']))
                page.evaluate('document.querySelector(".rb-live input[value=%s]").click(); 1' % name)
            page.screenshot(os.path.join(args.work, 'ch%02d-panel.png' % n), full_page=False)

        # The same pages from a plain static server.
        server = serve(args.html)
        try:
            n = chapters[0]
            page = open_panel(browser, 'http://127.0.0.1:%d/ch%02d.html' % (server.server_address[1], n))
            if page.evaluate('!!window.raybookLive.panels[0].features'):
                compare_chapter(page, args, n, scenes[n], 'http://')
        finally:
            server.shutdown()

        autorender(browser, args, chapters[0], scenes[chapters[0]])
        progressive(browser, args, scenes)
        if not args.skip_limits:
            limits(browser, args, chapters[0], scenes[chapters[0]])
        if args.bad_input:
            bad_input(browser, args, chapters[0], scenes[chapters[0]])

    if failures:
        print('live_panel: %d check(s) failed: %s' % (len(failures), '; '.join(failures)))
        return 1
    print('live_panel: all checks passed')
    return 0


def limits(browser, args, n, scene_name):
    page = open_panel(browser, 'file://%s/ch%02d.html' % (args.html, n))
    if not page.evaluate('!!window.raybookLive.panels[0].features'):
        return
    original = page.evaluate('window.raybookLive.panels[0].original')
    lines = original.split('\n')

    def native_message(text):
        path = os.path.join(args.work, scene_name)
        with open(path, 'w') as f:
            f.write(text)
        r, _ = native(args.rt, 'all', path, os.path.join(args.work, 'never.png'))
        return r.returncode, r.stderr.replace(path, scene_name)

    def page_message(text):
        t0 = time.time()
        r = render(page, '{size: "%s", text: %s}' % (SIZE, json_str(text)), args.timeout)
        shown = panel_text(page)
        return r['code'], terminal(r['err']).replace('/scenes/' + scene_name, scene_name), shown, time.time() - t0

    # A broken call: gr.sphere with a number for its name, on line 5.
    broken = '\n'.join(lines[:4] + ['gr.sphere(1, 2, 3)'] + lines[4:])
    ncode, nmsg = native_message(broken)
    pcode, pmsg, shown, secs = page_message(broken)
    want = scene_name + ':5:'
    check(ncode == 1 and pcode == 1 and want in pmsg and pmsg.strip() == nmsg.strip()
          and nmsg.strip().split('\n')[-1].replace(scene_name, '/scenes/' + scene_name) in shown,
          'a broken call shows the command line\'s message in the panel (%s ...)' % want,
          'native (%d): %s\npage (%d): %s\npanel shows: %s' % (ncode, nmsg, pcode, pmsg, shown))

    # An endless loop stops at the instruction limit with the command line's message, and the
    # page answers while it runs.
    loop = 'while true do end\n' + original
    ncode, nmsg = native_message(loop)
    page.evaluate('window.rbLoop = window.raybookLive.panels[0].render({size: "%s", text: %s}).catch(e => ({code: -1, err: String(e)})); 1'
                  % (SIZE, json_str(loop)))
    time.sleep(1.0)
    lag = []
    for _ in range(5):
        t0 = time.time()
        page.evaluate('document.querySelector(".rb-live .rb-status").textContent')
        lag.append(time.time() - t0)
        time.sleep(0.2)
    # A page frozen by the loop would answer only when it ends, after several seconds; 3 s leaves
    # room for a machine busy with other tests.
    check(max(lag) < 3.0, 'the page answers during an endless loop (slowest answer %.3f s)' % max(lag))
    t0 = time.time()
    r = page.evaluate('window.rbLoop', args.timeout)
    secs = time.time() - t0 + 2.0
    pmsg = terminal(r['err']).replace('/scenes/' + scene_name, scene_name)
    shown = panel_text(page)
    check(ncode == 1 and r['code'] == 1 and 'Lua instructions' in pmsg and pmsg.strip() == nmsg.strip()
          and 'ran more than' in shown,
          'an endless loop stops with the command line\'s message (after about %.0f s in the page)' % secs,
          'native (%d): %s\npage (%s): %s\npanel shows: %s' % (ncode, nmsg, r.get('code'), pmsg, shown))

    # The same rt instance, after an error and an endless loop, still renders the scene as the
    # command line does.
    compare_chapter(page, args, n, scene_name, 'after the errors', original)

    # Stop ends a render at once; the next render works.
    page.evaluate('window.rbStop = window.raybookLive.panels[0].render({size: "%s", text: %s}).then(r => "finished", e => String(e)); 1'
                  % (SIZE, json_str(loop)))
    time.sleep(1.5)
    page.evaluate('document.querySelector(".rb-live button.rb-stop").click(); 1')
    stopped = page.evaluate('window.rbStop', 10)
    status = page.evaluate('document.querySelector(".rb-live .rb-status").textContent')
    check('stopped' in stopped and 'stopped' in status, 'Stop ends an endless render at once',
          'render: %s, status: %s' % (stopped, status))
    compare_chapter(page, args, n, scene_name, 'after Stop', original)
    page.screenshot(os.path.join(args.work, 'ch%02d-after-stop.png' % n), full_page=False)


def autorender(browser, args, n, scene_name):
    """?rb-autorender=WxH: the first panel renders on load, and the page leaves the result."""
    page = browser.open('file://%s/ch%02d.html?rb-autorender=%s' % (args.html, n, SIZE))
    try:
        page.wait_for('document.getElementById("rb-autorender-result")', args.timeout)
        r = json.loads(page.evaluate('document.getElementById("rb-autorender-result").textContent'))
    except cdp.CdpError as e:
        check(False, '?rb-autorender=%s renders chapter %d\'s panel on load' % (SIZE, n), str(e))
        return
    same_as_native(args, r, n, scene_name, '?rb-autorender')


# A render long enough for previews (issue 38): chapter 18's Cornell box with 144 samples a
# pixel in place of the scene's 64, at 80x60 (20 tiles: rt's progress bar, which starts the
# previews, draws once the first is done).
PROGRESSIVE = (18, '80x60', 'samples = 64}', 'samples = 144}')


def progressive(browser, args, scenes):
    """The panel draws previews of growing sample counts, then the picture itself."""
    n, size, old, new = PROGRESSIVE
    html = os.path.join(args.html, 'ch%02d.html' % n)
    if n not in scenes or not os.path.exists(html):  # an export of an earlier chapter
        print('live_panel: no chapter %d page; the progressive render is not checked' % n)
        return
    page = open_panel(browser, 'file://' + html)
    if not page.evaluate('!!window.raybookLive.panels[0].features'):
        return
    original = page.evaluate('window.raybookLive.panels[0].original')
    if not check(old in original, 'chapter %d\'s scene has "%s" to raise' % (n, old)):
        return
    text = original.replace(old, new)
    r = render(page, '{size: "%s", text: %s}' % (size, json_str(text)), args.timeout)
    same_as_native(args, r, n, scenes[n], 'progressive', text, size)
    frames = (r or {}).get('frames') or []
    shown = ', '.join('%s (%s, after %.1f s)' % (f['label'], f['size'], f['at'] / 1000) for f in frames)
    check(len(frames) >= 2, 'a %.1f s render in the page shows %d previews before the picture '
          '(at least 2): %s' % ((r or {}).get('ms', 0) / 1000, len(frames), shown), repr(r and r['err']))
    # Their order: rt --preview's quarter size at one sample a pixel, then the full size at 1,
    # 4, 16, ... samples a pixel; each drawn as an image of its size.
    w, h = (int(v) for v in size.split('x'))
    want = [('%dx%d' % ((w + 2) // 4, (h + 2) // 4), 1)] + [(size, 4 ** k) for k in range(len(frames))]
    got = [(f['size'], f['spp']) for f in frames]
    check(got == want[:len(frames)], 'the previews grow: %s' % got, 'expected %s' % want[:len(frames)])
    for k, f in enumerate(frames):
        path = os.path.join(args.work, 'ch%02d-preview-%d.png' % (n, k))
        save_canvas(f, path)
        fw, fh, _ = png_pixels(path)
        check('%dx%d' % (fw, fh) == f['size'], 'preview %d is drawn at its size %s' % (k, f['size']),
              'drawn %dx%d' % (fw, fh))


# Cases that reach a file through the repository's layout (tests/bad_input/cases/../../../scenes),
# which neither the page's /scenes nor the native copy here has.
LAYOUT_CASES = {'media-vdb-grid-name.lua'}

# Cases whose message the page's Lua cannot yet give as native rt does (a known defect of
# src/web/lua_shim.cpp, not of the scene reader): an error() value that is a table reaches the
# shim as nil, so the page says "a nil" without the line; and an error inside table.sort's
# comparison names the line of the table.sort call, not the comparison's. For these the page
# must still fail with exit code 1 and the same message once its "file:line:" is taken out;
# the native messages are checked by tests/bad_input.
PAGE_DIFFERS = {'error-table.lua', 'sort-callback.lua'}

# Cases the page would repeat at great cost, each checked elsewhere: graph-deep-no-render's
# 200,000 nested nodes are 800,000 calls over the page's Lua bridge, about 150 s there against
# 0.4 s natively (tests/bad_input runs it natively; graph-deep-chain's 20,000 take the same
# path through the bridge in the page, and the freeing without recursion is the same C++); and
# endless-loop, whose message limits() compares with native rt's already (unless --skip-limits).
PAGE_SLOW = {'graph-deep-no-render.lua', 'endless-loop.lua'}


def without_place(message):
    """The message with its 'FILE:LINE: ' prefix and what the page cannot know taken out."""
    m = re.sub(r'^rt: error: (\S+?:\d+: )?', 'rt: error: ', message)
    return re.sub(r'whose value is a \w+', 'whose value is a VALUE', m)


def bad_input(browser, args, n, scene_name):
    """tests/bad_input/cases in the page's text box: each must fail with native rt's message.

    Native rt runs each case as WORK/scenes/NAME.lua from WORK, the page's rt as /scenes/NAME.lua
    from /, so the messages must be equal once WORK is taken out of the native one (the folders
    searched for a missing file, a path that climbs out of the scene's folder). Left out: cases
    with rt-args (the panel has no such control), cases of later chapters (skip-if-feature),
    cases that load the suite's broken OBJ files (not in the page), cases that render with
    the panel's --output (output-dir-*), LAYOUT_CASES and PAGE_SLOW. memory-string-rep hits the page's
    own memory limit (what wasm32 leaves): only its first words are compared."""
    cases_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'bad_input', 'cases')
    page = open_panel(browser, 'file://%s/ch%02d.html' % (args.html, n))
    if not page.evaluate('!!window.raybookLive.panels[0].features'):
        return
    # A short folder: Lua names a chunk whose path is longer than 60 bytes by its last ones
    # ("...ld/live_panel/bad_input/scenes/x.lua:3:"), so under a long --work the native message
    # would not read WORK/scenes/NAME.lua.
    # WORK's parent stands for the page's / too: '../x' from WORK is PARENT/x natively, /x there.
    parent = os.path.realpath(tempfile.mkdtemp(prefix='rb-live-'))
    work = os.path.join(parent, 'w')
    os.makedirs(os.path.join(work, 'scenes'))
    ran = same = 0
    for case in sorted(os.listdir(cases_dir)):
        if not case.endswith('.lua') or case.startswith('output-dir') or case in LAYOUT_CASES:
            continue
        if case in PAGE_SLOW and (case != 'endless-loop.lua' or not args.skip_limits):
            continue
        text = open(os.path.join(cases_dir, case), encoding='utf-8', errors='replace').read()
        if re.search(r'^-- (rt-args|skip-if-feature):', text, re.M) or re.search(r'objs/|\.obj[\'"]', text):
            continue
        path = os.path.join(work, 'scenes', scene_name)
        with open(path, 'w') as f:
            f.write(text)
        r = subprocess.run([args.rt, '--features=all', '--size', '16x12', '--threads', '1',
                            '--output', '/tmp/out.png', path], capture_output=True, text=True, cwd=work)
        native_msg = r.stderr.strip().replace(work, '').replace(parent, '')
        t0 = time.time()
        try:
            p = render(page, '{size: "16x12", text: %s}' % json_str(text), args.timeout)
            page_code, page_msg = p['code'], terminal(p['err']).strip()
        except cdp.CdpError as e:
            page_code, page_msg = -1, 'the render failed: %s' % e
            page = open_panel(browser, 'file://%s/ch%02d.html' % (args.html, n))
        ran += 1
        if case in PAGE_DIFFERS:
            ok = r.returncode == page_code == 1 and without_place(native_msg) == without_place(page_msg)
        elif case == 'memory-string-rep.lua':
            cut = lambda m: m.split(' of ')[0]
            ok = r.returncode == page_code == 1 and cut(native_msg) == cut(page_msg)
        else:
            ok = r.returncode == page_code == 1 and native_msg == page_msg
        same += ok
        check(ok, 'bad input %s: the page fails as native rt does (%.1f s)' % (case, time.time() - t0),
              'native (%d): %s\npage (%d): %s' % (r.returncode, native_msg, page_code, page_msg))
    shutil.rmtree(parent, ignore_errors=True)
    print('live_panel: %d of %d bad-input cases give native rt\'s message in the page' % (same, ran))


def json_str(s):
    return json.dumps(s)


if __name__ == '__main__':
    sys.exit(main())
