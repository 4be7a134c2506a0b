"""bench/peers/run.sh's table: each side's median wall and CPU over the pairs, the ratios, the
coverage each reached, and what the MuJoCo model approximates.
  summary.py RUNS BUILD SEED LOAD_BEFORE LOAD_AFTER
RUNS: one line a run, `aula|mujoco WALL_S USER_S SYS_S JSON` (Aula's --report, or mujoco_vacuum.py's line)."""
import json
import statistics
import sys


def read_runs(path):
    runs = {"aula": [], "mujoco": []}
    with open(path) as lines:
        for line in lines:
            side, wall_s, user_s, sys_s, report = line.split(" ", 4)
            runs[side].append({"wall_s": float(wall_s), "cpu_s": float(user_s) + float(sys_s), "user_s": float(user_s),
                               "sys_s": float(sys_s), **json.loads(report)})
    return runs


def median(runs, key):
    return statistics.median(r[key] for r in runs)


def spread(runs, key):
    values = sorted(r[key] for r in runs)
    return f"{median(runs, key):6.2f} s ({values[0]:.2f}-{values[-1]:.2f})"


def coverages(runs):
    values = sorted({f"{r['coverage_percent']:.6f}" for r in runs})
    return ", ".join(values) + " %"


def main(argv):
    if len(argv) != 6:
        print("usage: " + __doc__.split("\n")[2].strip(), file=sys.stderr)
        sys.exit(2)
    runs = read_runs(argv[1])
    aula, mujoco = runs["aula"], runs["mujoco"]
    version = mujoco[0]["mujoco"]
    print(f"The peers' job: {aula[0]['sim_time_s']:.0f} s of the vacuum house, bounce, seed {argv[3]}; "
          f"{len(aula)} pairs alternated (Aula, MuJoCo); load average {argv[4]} before, {argv[5]} after")
    print(f"{'':34} {'wall median (min-max)':>24} {'CPU median (min-max)':>24}  coverage")
    print(f"{'Aula (' + argv[2] + ')':34.34} {spread(aula, 'wall_s'):>24} {spread(aula, 'cpu_s'):>24}"
          f"  {coverages(aula)}")
    print(f"{'MuJoCo ' + version + ' (Python), whole':34} {spread(mujoco, 'wall_s'):>24} {spread(mujoco, 'cpu_s'):>24}"
          f"  {coverages(mujoco)}")
    print(f"{'MuJoCo ' + version + ', stepping only':34} {spread(mujoco, 'step_wall_s'):>24}"
          f" {spread(mujoco, 'step_cpu_s'):>24}")
    print(f"{'MuJoCo ' + version + ', its laser scans':34} {'':>24} {spread(mujoco, 'laser_cpu_s'):>24}")
    print(f"CPU medians, user + system: Aula {median(aula, 'user_s'):.2f} + {median(aula, 'sys_s'):.2f} s, "
          f"MuJoCo {median(mujoco, 'user_s'):.2f} + {median(mujoco, 'sys_s'):.2f} s")
    wall, cpu = median(aula, "wall_s") / median(mujoco, "wall_s"), median(aula, "cpu_s") / median(mujoco, "cpu_s")
    print(f"Aula / MuJoCo whole: wall {wall:.2f}x, CPU {cpu:.2f}x "
          f"({'Aula ahead' if wall < 1 else 'MuJoCo ahead'} on wall time, median of the pairs)")
    print(f"Bumps: Aula {median(aula, 'bumps'):.0f}, MuJoCo {median(mujoco, 'bumps'):.0f} (contact starts); "
          f"floor {aula[0]['floor_area_m2']} m2 (Aula), {mujoco[0]['floor_area_m2']} m2 (MuJoCo)")
    print("What differs (docs/performance.md, \"Peers\"): MuJoCo's soft contacts against DART's hard ones (Bullet's\n"
          "detector), its bumper reading contacts within 1 mm; a velocity actuator against DART's servo constraint,\n"
          "with the same force limits; the laser by mj_multiRay (the same ranges as Aula's: compare_with_aula.py);\n"
          "one Python process against Aula's simulator, component and referee in signed lockstep; the coverage\n"
          "counted once at the end. A bounce run is chaotic: the two coverages differ as two seeds do.")


if __name__ == "__main__":
    main(sys.argv)
