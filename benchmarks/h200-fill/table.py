#!/usr/bin/env python3
"""Mrays/s per scene, mode, size and build from run.sh's times.csv (best of the rounds), and each
build's 256x256 rate over its own 1920x1080 rate."""
import csv
import sys
from collections import defaultdict

best = defaultdict(float)
builds, sizes, rows = [], [], []
for r in csv.DictReader(open(sys.argv[1])):
    rate = int(r['rays']) / float(r['wall_s']) / 1e6
    key = (r['scene'], r['depth'], r['mode'])
    best[key + (r['build'], r['size'])] = max(best[key + (r['build'], r['size'])], rate)
    for lst, v in ((builds, r['build']), (sizes, r['size']), (rows, key)):
        if v not in lst:
            lst.append(v)

small, large = sizes[0], sizes[-1]
head = ['scene', 'mode'] + [f'{b} {s}' for b in builds for s in sizes] + [f'{b} ratio' for b in builds]
print('| ' + ' | '.join(head) + ' |')
print('|' + '---|' * len(head))
for scene, depth, mode in rows:
    name = scene if depth == '-' else f'{scene} depth {depth}'
    cells = [name, mode]
    for b in builds:
        for s in sizes:
            v = best.get((scene, depth, mode, b, s))
            cells.append(f'{v:.0f}' if v else '-')
    for b in builds:
        a, c = best.get((scene, depth, mode, b, small)), best.get((scene, depth, mode, b, large))
        cells.append(f'{a / c:.2f}' if a and c else '-')
    print('| ' + ' | '.join(cells) + ' |')
