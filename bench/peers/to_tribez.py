"""Write a case (workload.py) as tribez's own input files: a patch file and a CSV of points.

    python to_tribez.py CASE.json PATCH.toml [POINTS.csv]

The patch file lists the control points by multi-index "i,j,k" (i + j + k = n), in the case's
canonical order; the points file has one point per line, "a/q,b/q,c/q" as the case writes them.
"""

import json
import sys


def main():
    case_path, patch_path = sys.argv[1], sys.argv[2]
    with open(case_path) as f:
        case = json.load(f)
    n = case["degree"]
    idx = [(n - j - k, j, k) for k in range(n + 1) for j in range(n - k + 1)]
    rows = [
        f'"{i},{j},{k}" = [' + ", ".join(f'"{x}"' for x in p) + "]"
        for (i, j, k), p in zip(idx, case["nodes"])
    ]
    with open(patch_path, "w") as f:
        f.write(f"degree = {n}\n[control_points]\n" + "\n".join(rows) + "\n")
    if len(sys.argv) > 3:
        with open(sys.argv[3], "w") as f:
            for p in case["points"]:
                f.write(",".join(p) + "\n")


if __name__ == "__main__":
    main()
