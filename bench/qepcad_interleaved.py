#!/usr/bin/env python3
"""qepcad_interleaved.py -- recstab builds and QEPCAD B, interleaved (issue 13).

    python3 bench/qepcad_interleaved.py RUNS BIN[,BIN...]

On a loaded machine consecutive runs of bench_qepcad.sh differ by more than a
few ms; here every round runs each BIN and QEPCAD B once per case, so drift
hits all alike.  Prints the median CPU ms (user + sys of the child) and the
ratio QEPCAD / BIN.  The cases and QEPCAD inputs are bench_qepcad.sh's: the
input is the one the first BIN writes (`region P, Q` -> qepcad_input_for_all).
"""
import json, os, re, resource, statistics, subprocess, sys, tempfile

runs, bins = int(sys.argv[1]), sys.argv[2].split(',')
tmp = tempfile.mkdtemp(prefix='recstab_qei.')
hht = os.path.join(tmp, 'hht-free.case')
with open('cases/textbook/hht-alpha.case') as f:
    src = f.read()
with open(hht, 'w') as f:   # the range of alpha left open, as in bench_qepcad.sh
    f.write(re.sub(r'(?m)^assume w > 0, -1/3 <= alpha <= 0', 'assume w > 0', src))
cases = {   # name: (arguments before --analyse, P, Q, case file)
    'theta': ([], 'th', 'w', 'cases/forall/theta-oscillator.case'),
    'hht': ([], 'alpha', 'w', hht),
    'park': (['--set', 'm=1', '--set', 'muh=1'], 'alpha', 'wh', 'cases/park-staggered.case'),
}
qe = {'version': os.path.join(tmp, 'trivial.qe')}
with open(qe['version'], 'w') as f:
    f.write('[ trivial ]\n(x)\n1\n[ x > 0 ].\nfinish\n')
cmds = {'version': ['--version']}
for c, (pre, p, q, case) in cases.items():
    out = subprocess.run([bins[0], '--json'] + pre + ['--analyse', 'region %s, %s' % (p, q), case],
                         capture_output=True, text=True).stdout
    d = json.loads(out)
    d = d['cases'][0] if 'cases' in d else d
    qe[c] = os.path.join(tmp, c + '.qe')
    with open(qe[c], 'w') as f:
        f.write(d['results'][0]['qepcad_input_for_all'] + '\n')
    cmds[c] = pre + ['--analyse', 'region %s for all [%s]' % (p, q), case]

def cpu_ms(cmd, stdin='/dev/null'):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(stdin) as f:
        subprocess.run(cmd, stdin=f, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return 1000 * (r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)

res = {}
for _ in range(runs):
    for c in cmds:
        for b in bins:
            res.setdefault((b, c), []).append(cpu_ms([b] + cmds[c]))
        res.setdefault(('qepcad', c), []).append(cpu_ms(['qepcad', '+N1000000'], qe[c]))
for c in cmds:
    q = statistics.median(res[('qepcad', c)])
    print(c, 'qepcad=%.2f' % q, ' '.join('%s=%.2f (x%.2f)' % (b, statistics.median(res[(b, c)]),
                                                            q / statistics.median(res[(b, c)])) for b in bins))
for f in os.listdir(tmp):
    os.remove(os.path.join(tmp, f))
os.rmdir(tmp)
