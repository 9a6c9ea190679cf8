#!/usr/bin/env python3
# The speed table of BENCHMARKS.md, section h200-shared-loop, from times.csv (run.sh's output):
# ms per spp = (GPU time, else wall time) / spp of each render; the ratio is before / after of
# the best of the rounds (above 1: the shared loop is faster).
import collections, csv, os
rows = csv.DictReader(open(os.path.join(os.path.dirname(__file__), 'times.csv')))
ms = collections.defaultdict(list)
for r in rows:
    t = float(r['gpu_s']) if r['gpu_s'] else float(r['wall_s'])
    ms[(r['scene'], r['mode'], r['build'])].append(1000 * t / int(r['spp']))
print('| scene | engine | before (739d6cf), ms/spp | after, ms/spp | before / after |')
print('|---|---|---|---|---|')
for sc in ['cornell', 'bunny']:
    for m, label in [('embree', 'CPU, 16 threads'), ('compute', 'H200 compute'), ('pipeline', 'H200 pipeline')]:
        b, a = ms[(sc, m, 'before')], ms[(sc, m, 'after')]
        f = lambda v: ', '.join('%.3f' % x for x in v)
        print('| %s | %s | %s | %s | %.3f |' % (sc, label, f(b), f(a), min(b) / min(a)))
