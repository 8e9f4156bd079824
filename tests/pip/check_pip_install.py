"""`pip install .` in a fresh virtual environment, as docs/library.md tells users to do it.

Usage: python3 check_pip_install.py SOURCE WORK [BUILD_DIR]

Copies the checkout SOURCE (its git-tracked and untracked-but-not-ignored files: a clean
clone's content, without build folders) to WORK/src, makes WORK/venv with
`python3 -m venv --system-site-packages` (Debian's numpy, setuptools and wheel), runs
`pip install --no-build-isolation --no-index .` there (no network), then imports the
installed module from outside the checkout and checks that it is the installed one, that its
version is the package's and that it computes (the documented burn3d example).
With BUILD_DIR the install reuses that CMake build folder (setup.py, GRASSFIRE_BUILD_DIR):
the test then takes seconds; without it the module is configured and built from the copy.
Exits non-zero with the failing step's output.
"""
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path


def run(args, **kwargs):
    start = time.monotonic()
    p = subprocess.run(args, capture_output=True, text=True, check=False, **kwargs)
    print(f"$ {' '.join(map(str, args))}   ({time.monotonic() - start:.1f} s, exit {p.returncode})", flush=True)
    if p.returncode != 0:
        sys.stdout.write(p.stdout[-6000:])
        sys.stdout.write(p.stderr[-6000:])
        sys.exit(f"check_pip_install: step failed: {' '.join(map(str, args))}")
    return p.stdout


def checkout_files(source):
    try:
        out = subprocess.run(["git", "-C", str(source), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                             capture_output=True, check=True).stdout
        return [f for f in out.decode().split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        return [str(p.relative_to(source)) for p in source.rglob("*")
                if p.is_file() and not p.relative_to(source).parts[0].startswith(("build", ".git"))]


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    source, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
    build_dir = Path(sys.argv[3]).resolve() if len(sys.argv) == 4 else None
    shutil.rmtree(work, ignore_errors=True)
    src = work / "src"
    for f in checkout_files(source):
        if (source / f).is_file():
            (src / f).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source / f, src / f)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "GRASSFIRE_BUILD_DIR")}
    env["PIP_NO_INPUT"] = "1"
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    if build_dir:
        env["GRASSFIRE_BUILD_DIR"] = str(build_dir)
    venv = work / "venv"
    run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(venv)], env=env)
    python = venv / "bin" / "python"
    run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir", "."],
        cwd=src, env=env)
    check = (
        "import grassfire, importlib.metadata as m, sys\n"
        "print(grassfire.__file__)\n"
        "assert grassfire.__file__.startswith(sys.prefix), (grassfire.__file__, sys.prefix)\n"
        "assert m.version('grassfire') == grassfire.__version__, (m.version('grassfire'), grassfire.__version__)\n"
        "b = grassfire.burn3d('tube', method='exact', spacing=0.5)\n"
        "assert round(float(b['BT'].max()), 6) == 4.0, b['BT'].max()\n"
        "print('installed grassfire', grassfire.__version__, 'computes')\n")
    print(run([python, "-c", check], cwd=work, env=env), end="")
    print(run([python, "-m", "pip", "uninstall", "-y", "grassfire"], cwd=work, env=env).strip().splitlines()[-1])
    shutil.rmtree(work, ignore_errors=True)
    print("check_pip_install: ok")


if __name__ == "__main__":
    main()
