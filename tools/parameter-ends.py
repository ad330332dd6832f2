#!/usr/bin/python3
"""Runs every native plugin with all its real parameters at the ends of their ranges at once (every
combination; just inside an open end: the smallest normal number above 0), with alpha at 1 or 20
and beta at 7 or 50 (their upper ends), on map1 with 5 ants for 5 iterations. Prints each run that
blamed a plugin for an infinite or NaN value or crashed, then the count of each other refusal.
A plugin's ranges keep its arithmetic finite when none is printed. About 8 minutes.

Usage: tools/parameter-ends.py [ACOPLAN]   (default build/release/bin/acoplan)"""
import itertools, os, re, subprocess, sys
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ACOPLAN = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'build/release/bin/acoplan')
BASE = ['--map', os.path.join(ROOT, 'data/maps/classic20/map1.txt'), '--start', '0,0', '--goal', '19,19',
        '--ants', '5', '--iterations', '5', '--threads', '1']
TINY = 2.2250738585072014e-308

def ends(rng):
    m = re.fullmatch(r'([\(\[]?)([^:]+):([^\)\]]+)([\)\]]?)', rng)
    lo_open, lo, hi, hi_open = m.group(1) == '(', float(m.group(2)), float(m.group(3)), m.group(4) == ')'
    return [lo if not lo_open else (TINY if lo == 0 else lo * (1 + 1e-15)), hi if not hi_open else hi * (1 - 1e-15)]

listing = subprocess.run([ACOPLAN, '--list-plugins'], capture_output=True, text=True).stdout
plugins = [p for p in re.findall(r'^  (\w+/\w+) ', listing, re.M)
           if not p.endswith('/python') and not p.startswith(('map/', 'local/'))]
runs = blamed = other = 0
kinds = {}
for plugin in plugins:
    slot, name = plugin.split('/')
    desc = subprocess.run([ACOPLAN, '--describe', plugin], capture_output=True, text=True).stdout
    params = {n: ends(r) for n, r in re.findall(r'^  (\w+)  real  default \S+  range (\S+)', desc, re.M)}
    names = list(params)
    for values in itertools.product(*[params[n] for n in names]):
        for alpha, beta in itertools.product(['1', '20'], ['7', '50']):
            args = [ACOPLAN] + BASE + [f'--{slot}', name, '--alpha', alpha, '--beta', beta]
            for n, v in zip(names, values): args += [f'--{slot}.{n}', repr(v)]
            r = subprocess.run(args, capture_output=True, text=True)
            runs += 1
            err = r.stderr.strip()
            if r.returncode not in (0, 1):
                other += 1; print('CRASH', ' '.join(args[len(BASE)+1:]), r.returncode, err[:200])
            elif re.search(r' wrote (inf|-inf|nan|-nan)', err):
                blamed += 1; print('BLAMED', ' '.join(args[len(BASE)+1:]), '->', err[:240])
            elif r.returncode == 1:
                key = re.sub(r'[-+]?\d[\d.e+-]*', 'N', err)[:120]
                kinds[key] = kinds.get(key, 0) + 1
print(f'{runs} runs: {blamed} blamed a plugin for a non-finite value, {other} crashed')
for k, v in sorted(kinds.items(), key=lambda kv: -kv[1]): print(f'  {v:5d} x {k}')
