#!/usr/bin/env python3
"""Bundle raybook's live chapter panels into one script, raybook-live.js.

    python3 src/web/bundle.py --rt build-web/rt_web.js --lua-host src/web/lua_host.js \
        --wasmoon build-web/npm/node_modules/wasmoon --out docs/html/live

The chapter pages load it with a plain <script src="live/raybook-live.js">, which works from
file:// as well as from a server: Chromium refuses new Worker('file:///...') and fetch() of a
file:// URL, so nothing is loaded after the script. It holds

  - the worker's whole source as one string, started from a Blob URL: wasmoon's dist/index.js,
    lua_host.js, rt_web.js (rt's JavaScript half, built with emscripten) and src/web/worker.js;
  - the two WebAssembly modules, gzip'd, in base64: rt_web.wasm (rt, with scenes/ embedded at
    /scenes), which the page compiles once for every worker it starts, and wasmoon's glue.wasm
    (Lua 5.4). Outside the worker's source: the worker starts 0.4 MiB of script, not 3.7 MiB,
    and gzip makes the page's script 1.6 MiB, not 3.8 MiB;
  - the chapter scenes' texts (scenes/chapterNN-*.lua), which the panels put in their text box;
  - src/web/panel.css and src/web/panel.js, the panels.

Python's standard library only. Prints the bundle's size.
"""
import argparse
import base64
import gzip
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def read(path, mode='r'):
    with open(path, mode) as f:
        return f.read()


def js_string(text):
    # ensure_ascii: the bundle is plain ASCII whatever its sources hold (U+2028 included).
    return json.dumps(text, ensure_ascii=True)


def ascii_js(source):
    # panel.js writes its few non-ASCII characters (an ellipsis, a times sign) only in strings
    # and comments, where \uXXXX means the same: the bundle stays ASCII, whatever the page's
    # charset.
    return re.sub(r'[^\x00-\x7f]', lambda m: '\\u%04x' % ord(m.group(0)), source)


def gzip_base64(data):
    # mtime 0: the same inputs give the same bundle, byte for byte.
    return base64.b64encode(gzip.compress(data, 9, mtime=0)).decode('ascii')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--rt', required=True,
                    help='rt_web.js, emscripten build of rt (its rt_web.wasm next to it)')
    ap.add_argument('--lua-host', required=True, help='src/web/lua_host.js')
    ap.add_argument('--wasmoon', required=True,
                    help='the wasmoon package folder (node_modules/wasmoon)')
    ap.add_argument('--out', required=True, help='output folder, e.g. docs/html/live')
    ap.add_argument('--scenes', default=os.path.join(ROOT, 'scenes'),
                    help='folder of the chapter scenes (default: the repository\'s scenes/)')
    ap.add_argument('--name', default='raybook-live.js', help='output file name')
    args = ap.parse_args()
    rt_wasm_path = os.path.splitext(args.rt)[0] + '.wasm'
    for path, what in ((args.rt, 'make web builds it'), (rt_wasm_path, 'make web builds it'),
                       (args.lua_host, 'src/web/lua_host.js'),
                       (os.path.join(args.wasmoon, 'dist', 'index.js'),
                        'npm ci in the folder of src/web/package.json\'s copy installs it'),
                       (args.scenes, 'the repository\'s scenes/')):
        if not os.path.exists(path):
            sys.exit('bundle.py: %s is missing (%s)' % (path, what))

    wasmoon_pkg = json.loads(read(os.path.join(args.wasmoon, 'package.json')))
    wasmoon_js = read(os.path.join(args.wasmoon, 'dist', 'index.js'))
    glue = read(os.path.join(args.wasmoon, 'dist', 'glue.wasm'), 'rb')
    if glue[:4] != b'\0asm':
        sys.exit('bundle.py: %s is not a WebAssembly module' % os.path.join(args.wasmoon, 'dist', 'glue.wasm'))
    rt_wasm = read(rt_wasm_path, 'rb')
    if rt_wasm[:4] != b'\0asm':
        sys.exit('bundle.py: %s is not a WebAssembly module' % rt_wasm_path)
    wasmoon_license = ''
    for name in ('LICENSE', 'LICENSE.md', 'license'):
        p = os.path.join(args.wasmoon, name)
        if os.path.exists(p):
            wasmoon_license = read(p)
            break

    worker = '\n;\n'.join([
        '// wasmoon %s (dist/index.js)\n%s' % (wasmoon_pkg['version'], wasmoon_js),
        '// lua_host.js\n' + read(args.lua_host),
        '// rt_web.js\n' + read(args.rt),
        '// worker.js\n' + read(os.path.join(HERE, 'worker.js')),
    ])

    scenes = {}
    for name in sorted(os.listdir(args.scenes)):
        if re.fullmatch(r'chapter\d\d-[A-Za-z0-9_-]+\.lua', name):
            scenes[name] = read(os.path.join(args.scenes, name))
    if not scenes:
        sys.exit('bundle.py: no chapterNN-*.lua scenes in ' + args.scenes)

    license_comment = ''
    if wasmoon_license:
        license_comment = ('/* It contains wasmoon %s (https://github.com/ceifa/wasmoon), '
                           'Lua 5.4 compiled to WebAssembly (Lua: Copyright (C) 1994-2023 '
                           'Lua.org, PUC-Rio, MIT license, https://www.lua.org/license.html):'
                           '\n%s*/\n') % (
            wasmoon_pkg['version'], wasmoon_license.replace('*/', '* /'))
    bundle = ''.join([
        '/* raybook-live.js: the live chapter panels of raybook\'s docs. Generated by\n'
        '   src/web/bundle.py from src/web/ (panel.js, worker.js, panel.css, lua_host.js),\n'
        '   rt_web.js and the wasmoon npm package; do not edit. */\n',
        license_comment,
        '(function () {\n',
        'var RB_WORKER_SOURCE = %s;\n' % js_string(worker),
        'var RB_RT_WASM = "%s";\n' % gzip_base64(rt_wasm),
        'var RB_GLUE_WASM = "%s";\n' % gzip_base64(glue),
        'var RB_SCENES = %s;\n' % json.dumps(scenes, ensure_ascii=True, indent=0),
        'var RB_CSS = %s;\n' % js_string(read(os.path.join(HERE, 'panel.css'))),
        ascii_js(read(os.path.join(HERE, 'panel.js'))),
        '\n})();\n',
    ])

    os.makedirs(args.out, exist_ok=True)
    out = os.path.join(args.out, args.name)
    tmp = out + '.tmp'
    with open(tmp, 'w', encoding='ascii') as f:
        f.write(bundle)
    os.replace(tmp, out)
    print('bundle.py: wrote %s (%.1f MiB: rt_web.wasm %.1f MiB, gzip\'d %.1f MiB; the worker\'s '
          'script %.1f MiB; %d scenes)' % (
              out, os.path.getsize(out) / 2**20, len(rt_wasm) / 2**20,
              len(gzip.compress(rt_wasm, 9, mtime=0)) / 2**20, len(worker) / 2**20, len(scenes)))


if __name__ == '__main__':
    main()
