#!/usr/bin/env python3
"""What the CUDA module's device code costs: the largest functions of its PTX (instructions,
which is what makes cicc and ptxas slow and hungry) and, for every kernel, the deepest chain of
stack frames through the functions it calls (each recursive function counted once, as
core/backend/device_stack.h adds its levels itself).

Its inputs: the compile command of cuda_module.cu (`ninja -C build -t commands sheaf_cuda |
grep cuda_module.cu`) run with `-Xptxas -v` added (ptxas writes the frames to stderr), and
again with `-arch=compute_90 -ptx -o m.ptx` in place of its --generate-code, -c and -o options:

    python3 gpu/ptx_report.py ptxas.log m.ptx
"""
import argparse
import collections
import re
import sys

HEADER = re.compile(r'^(\.visible |\.weak )?\.(func|entry)')


def frames_of(log_path):
    """Stack frame bytes of every function and kernel in a ptxas -v log (the largest over
    the architectures)."""
    frames, name = {}, None
    with open(log_path, errors='replace') as f:
        for line in f:
            m = re.search(r"Compiling entry function '(\w+)'", line) or re.search(
                r'Function properties for (\w+)', line)
            if m:
                name = m.group(1)
                continue
            m = re.search(r'(\d+) bytes stack frame', line)
            if m and name:
                frames[name] = max(frames.get(name, 0), int(m.group(1)))
                name = None
    return frames


def parse_ptx(ptx_path):
    """Instruction counts, callees and kernel names of the functions defined in a PTX file."""
    with open(ptx_path, errors='replace') as f:
        lines = f.read().split('\n')
    sizes, calls, kernels = {}, collections.defaultdict(set), []
    i = 0
    while i < len(lines):
        line = lines[i]
        if HEADER.match(line):
            m = re.search(r'(_Z\w+|\w+)\s*\(?\s*$', line) or re.search(r'(_Z\w+)', line)
            name = m.group(1) if m else line
            j = i + 1
            while j < len(lines) and lines[j] not in ('{', ';'):
                j += 1
            if j < len(lines) and lines[j] == '{':  # a definition, not a prototype
                if '.entry' in line:
                    kernels.append(name)
                count, k = 0, j + 1
                while k < len(lines) and lines[k] != '}':
                    body = lines[k]
                    if body.startswith('\t') and not body.startswith(('\t//', '\t.')):
                        count += 1
                    if 'call' in body:
                        for t in lines[k:k + 3]:
                            c = re.search(r'(_Z\w+)', t)
                            if c:
                                calls[name].add(c.group(1))
                                break
                    k += 1
                sizes[name] = count
                i = k
        i += 1
    return sizes, calls, kernels


def deepest(name, frames, calls, seen=()):
    if name in seen:
        return 0, []
    best = (0, [])
    for callee in calls.get(name, ()):
        got = deepest(callee, frames, calls, seen + (name,))
        if got[0] > best[0]:
            best = got
    return frames.get(name, 0) + best[0], [name] + best[1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument('ptxas_log')
    ap.add_argument('ptx')
    ap.add_argument('--top', type=int, default=12, help='rows of each table')
    a = ap.parse_args()
    frames = frames_of(a.ptxas_log)
    sizes, calls, kernels = parse_ptx(a.ptx)
    if not sizes:
        sys.exit(f'{a.ptx}: no function definitions found')
    print(f'{sum(sizes.values())} PTX instructions in {len(sizes)} functions; the largest:')
    for name, n in sorted(sizes.items(), key=lambda x: -x[1])[:a.top]:
        print(f'  {n:8d}  {name[:120]}')
    chains = sorted(((*deepest(k, frames, calls), k) for k in kernels), reverse=True)
    print('\nDeepest stack chains (bytes; recursive functions once):')
    for total, path, kernel in chains[:a.top]:
        print(f'  {total:6d}  {kernel[:110]}')
        print(f'      {frames.get(kernel, 0):6d}  (its own frame)')
        for f in path[1:]:
            print(f'      {frames.get(f, 0):6d}  {f[:100]}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
