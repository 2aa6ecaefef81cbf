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
of --runs renders; the page's first render (which starts rt) is not counted. Each chapter gets a page of its own in a temporary folder next to a copy of the bundle.
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
             '| chapter | scene | native (s) | page callMain (s) | page wall (s) | ratio callMain / native | first picture in the page (s) | previews | rt start in the page (s) |',
             '|---:|---|---:|---:|---:|---:|---:|---:|---:|']
    print('\n'.join(lines))
    sys.stdout.flush()

    tmp = tempfile.mkdtemp(prefix='rb-bench-live-')
    try:
        os.makedirs(os.path.join(tmp, 'live'))
        shutil.copy(args.bundle, os.path.join(tmp, 'live', 'raybook-live.js'))
        with cdp.Browser() as browser:
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


def bench_chapter(browser, args, tmp, n, scene):
    page_file = os.path.join(tmp, 'ch%02d.html' % n)
    with open(page_file, 'w') as f:
        f.write('<!DOCTYPE html><html><head><meta charset="utf-8"><title>bench %d</title></head>'
                '<body><div class="rb-live" data-scene="%s" data-chapter="%d"></div>'
                '<script src="live/raybook-live.js"></script></body></html>\n' % (n, scene, n))
    t0 = time.time()
    page = browser.open('file://' + page_file)
    try:
        page.wait_for('window.raybookLive && window.raybookLive.panels[0].features', 300)
    except cdp.CdpError as e:
        return '| %d | %s | | | | | rt did not start: %s |' % (n, scene, e)
    start = time.time() - t0

    def render():
        t = time.time()
        r = page.evaluate('window.raybookLive.panels[0].render({size: "%s"})' % args.size, args.timeout)
        return r, time.time() - t

    r, _ = render()  # the first render: not counted
    if r['code'] != 0:
        return '| %d | %s | | | | | failed: %s |' % (n, scene, r['err'].strip().replace('\n', ' '))
    features = r['args'][0]
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
    return '| %d | `%s` | %.3f | %.3f | %.3f | %.2f | %.3f | %s | %.2f |' % (
        n, scene, nat, call, wall, call / nat, first, shown, start)


if __name__ == '__main__':
    main()
