"""Wall-clock time of a whole process, start to exit, over several runs.

    python wall.py RUNS OUT_FILE COMMAND [ARG ...]

Runs COMMAND RUNS times after one warm-up run, its standard output written to OUT_FILE (the last
run's output stays there), and prints one JSON line: the best and the median wall time in seconds,
and the best and the median CPU time (user + system, all threads) of the process.
"""

import json
import resource
import statistics
import subprocess
import sys
import time


def main():
    runs, out, cmd = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
    times, cpus = [], []
    for i in range(runs + 1):
        with open(out, "wb") as f:
            r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            subprocess.run(cmd, stdout=f, check=True)
            t = time.perf_counter() - t0
            r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        if i > 0:
            times.append(t)
            cpus.append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
    print(json.dumps({
        "runs": runs, "best": min(times), "median": statistics.median(times),
        "cpu_best": min(cpus), "cpu_median": statistics.median(cpus),
    }))


if __name__ == "__main__":
    main()
