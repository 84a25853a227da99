#!/usr/bin/env python3
"""A fixed reference load, to say which phase the (shared) machine is in
when a wall-clock figure is measured: run it beside the measurement and
quote its two times with it (doc/state_iteration.md). A Python loop of 3
million steps at module level (the processor; its global variables make
it slower than the same loop in a function, keep it as it is) and 200
numpy passes over 2 million doubles (the memory bus), one thread each.

    OPENBLAS_NUM_THREADS=1 python3 scripts/machine_reference.py
"""
import time

import numpy as np

start = time.time()
total = 0
for i in range(3_000_000):
    total += i * i
loop = time.time() - start
x = np.random.rand(2_000_000)
start = time.time()
for _ in range(200):
    x = x * 1.0000001 + 0.5
stream = time.time() - start
print(f"py loop {loop:.2f} s, numpy stream {stream:.2f} s")
