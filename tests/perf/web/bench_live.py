#!/usr/bin/env python3
"""bench_live: the live panels' cost. A benchmark, never a test: it prints numbers, not verdicts.

    python3 tests/perf/web/bench_live.py --bundle docs/html/live/raybook-live.js --rt build/rt_ch17 \
        [--chapters 1-17] [--size 160x120] [--runs 3] [--out bench-live.md]

Records the bundle's size (and gzip's, what a server would send) and, for each chapter's scene,
the time to render it at 160x120 in headless Chromium (the panel's rt in its Web Worker: the
callMain time the worker measures, and the wall time of a render seen from the page, which adds
the messages and drawing the PNG) against native `rt --threads 1` on the same scene with the
same options (wall time of the process), as a Markdown table with the ratio page / native, and
when the page showed its first picture (its first preview, else the picture itself) with the
number of previews before the picture (src/web/panel.js renders them in a second worker).
Each time is the least (--stat min, the default: a busy machine only adds time) or the median
of --runs renders; the page's first render is not counted. Each chapter gets a page of its own
in a temporary folder next to a copy of the bundle, opened in a new tab of one browser.

And from that fresh page load, in the page's own clock (performance.now(), which starts when the
page starts to load): when the panel's rt was ready to render (its worker started, rt
instantiated and its --list-features run), and when the first picture (a preview or the picture)
was drawn by the first render, which the benchmark asks for as soon as the page has loaded and
which starts once rt is ready, as a reader's click on Render would. --startup-runs N opens
each chapter's page N more times for these two (the least is shown, and the first page of the
browser's life, when Chromium itself is cold, apart).
"""
import argparse
import gzip
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'web'))
import cdp  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'))


def chapters_arg(text):
    out = []
    for part in text.split(','):
        if '-' in part:
            a, b = part.split('-')
            out += list(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--bundle', default=os.path.join(ROOT, 'docs', 'html', 'live', 'raybook-live.js'))
    ap.add_argument('--rt', default=os.path.join(ROOT, 'build', 'rt_ch17'), help='native rt')
    ap.add_argument('--scenes', default=os.path.join(ROOT, 'scenes'))
    ap.add_argument('--chapters', default='1-17', type=chapters_arg)
    ap.add_argument('--size', default='160x120')
    ap.add_argument('--runs', type=int, default=5)
    ap.add_argument('--stat', choices=('min', 'median'), default='min',
                    help='of the runs: min (least disturbed by a busy machine) or median')
    ap.add_argument('--timeout', type=float, default=600, help='seconds for one render in the page')
    ap.add_argument('--startup-runs', type=int, default=0,
                    help='open each page this many more times, for the ready and first-picture times')
    ap.add_argument('--out', help='also write the Markdown here')
    args = ap.parse_args()

    scenes = {}
    for name in os.listdir(args.scenes):
        m = re.fullmatch(r'chapter(\d\d)-.*\.lua', name)
        if m:
            scenes[int(m.group(1))] = name

    size = os.path.getsize(args.bundle)
    with open(args.bundle, 'rb') as f:
        gz = len(gzip.compress(f.read(), 9))
    lines = ['# raybook live panels: bundle size and render times', '',
             'bundle `%s`: %.2f MiB (%d bytes), %.2f MiB gzip -9' % (
                 os.path.basename(args.bundle), size / 2**20, size, gz / 2**20), '',
             'Renders at %s, %s of %d runs; native: `%s --threads 1` (process wall time); '
             'page: headless Chromium %s, the worker\'s callMain time and the page\'s wall '
             'time for one render.' % (args.size, args.stat, args.runs, os.path.basename(args.rt),
                                       chromium_version()), '',
             'Ready and first picture after open: in the page\'s clock, from the start of its load '
             '(%s); the first render asked for at once, at %s.' % (
                 'the least of %d loads' % (args.startup_runs + 1) if args.startup_runs else 'one load',
                 args.size), '',
             '| chapter | scene | native (s) | page callMain (s) | page wall (s) | ratio callMain / native | first picture in the page (s) | previews | ready after open (s) | first picture after open (s) |',
             '|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|']
    print('\n'.join(lines))
    sys.stdout.flush()

    tmp = tempfile.mkdtemp(prefix='rb-bench-live-')
    try:
        os.makedirs(os.path.join(tmp, 'live'))
        shutil.copy(args.bundle, os.path.join(tmp, 'live', 'raybook-live.js'))
        with cdp.Browser() as browser:
            # The browser's first page (Chromium's own start, nothing compiled yet) apart.
            page, ready, first, _ = open_page(browser, args, tmp, args.chapters[0],
                                             scenes[args.chapters[0]])
            page.send('Page.close')
            cold = ('The browser\'s first page (chapter %d, Chromium cold): ready %.2f s, first '
                    'picture %.2f s after open.' % (args.chapters[0], ready, first))
            lines.insert(len(lines) - 3, cold)
            lines.insert(len(lines) - 3, '')
            print(cold + '\n')
            for n in args.chapters:
                if n not in scenes:
                    continue
                row = bench_chapter(browser, args, tmp, n, scenes[n])
                lines.append(row)
                print(row)
                sys.stdout.flush()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if args.out:
        with open(args.out, 'w') as f:
            f.write('\n'.join(lines) + '\n')


def chromium_version():
    try:
        return subprocess.run([cdp.find_chromium(), '--version'], capture_output=True,
                              text=True).stdout.strip().split('\n')[-1]
    except Exception:
        return '(unknown)'


# A fresh page with chapter N's panel, its first render asked for as soon as it has loaded.
# Returns the page, and when (seconds in the page's clock) rt was ready and the first render's
# first picture was drawn, and rt's arguments; raises CdpError if rt did not start or the render failed.
def open_page(browser, args, tmp, n, scene):
    page_file = os.path.join(tmp, 'ch%02d.html' % n)
    with open(page_file, 'w') as f:
        f.write('<!DOCTYPE html><html><head><meta charset="utf-8"><title>bench %d</title></head>'
                '<body><div class="rb-live" data-scene="%s" data-chapter="%d"></div>'
                '<script src="live/raybook-live.js"></script></body></html>\n' % (n, scene, n))
    page = browser.open('file://' + page_file)
    r = page.evaluate('(async () => { const p = window.raybookLive.panels[0]; await p.start(); '
                      'const r = await p.render({size: "%s"}); return {code: r.code, err: r.err, '
                      'args: r.args, '
                      'ready: p.readyInfo.at, t0: r.t0, shown: r.shown, '
                      'first: r.frames.length ? r.t0 + r.frames[0].at : r.shown}; })()' % args.size,
                      args.timeout)
    if r['code'] != 0:
        raise cdp.CdpError('failed: ' + r['err'].strip().replace('\n', ' '))
    return page, r['ready'] / 1000, r['first'] / 1000, r['args']


def bench_chapter(browser, args, tmp, n, scene):
    try:
        # The first render (which also warms up the browser's compiled code): not counted.
        page, ready, first_open, rt_args = open_page(browser, args, tmp, n, scene)
        for _ in range(args.startup_runs):
            page.send('Page.close')
            page, ready2, first2, _ = open_page(browser, args, tmp, n, scene)
            ready, first_open = min(ready, ready2), min(first_open, first2)
    except cdp.CdpError as e:
        return '| %d | %s | | | | | %s |' % (n, scene, e)

    def render():
        t = time.time()
        r = page.evaluate('window.raybookLive.panels[0].render({size: "%s"})' % args.size, args.timeout)
        return r, time.time() - t

    features = rt_args[0]
    calls, walls, firsts, previews = [], [], [], []
    for _ in range(args.runs):
        r, wall = render()
        calls.append(r['ms'] / 1000)
        walls.append(wall)
        firsts.append(r['frames'][0]['at'] / 1000 if r['frames'] else wall)
        previews.append(len(r['frames']))
    natives = []
    for _ in range(args.runs):
        t = time.time()
        subprocess.run([args.rt, features, '--quiet', '--size', args.size, '--threads', '1',
                        '--output', os.path.join(tmp, 'native.png'), os.path.join(args.scenes, scene)],
                       check=True, stdout=subprocess.DEVNULL)
        natives.append(time.time() - t)
    page.send('Page.close')
    pick = min if args.stat == 'min' else statistics.median
    nat, call, wall, first = (pick(x) for x in (natives, calls, walls, firsts))
    shown = '%d' % min(previews) if min(previews) == max(previews) else '%d-%d' % (min(previews), max(previews))
    return '| %d | `%s` | %.3f | %.3f | %.3f | %.2f | %.3f | %s | %.2f | %.2f |' % (
        n, scene, nat, call, wall, call / nat, first, shown, ready, first_open)


if __name__ == '__main__':
    main()
