"""The web build (docs/web.md): the `web` preset compiled with Debian's
Emscripten, and its programs run under Node.js as a native program runs.

build_web(folder) configures and builds the preset's `pathlab` (pathlab.js
and pathlab.wasm) there; node_command(folder) is the command line that runs
it. Emscripten 3.1.6 fetches its .wasm with the fetch() that Node.js 18 and
later define, which does not take a file path: it must read it as a file.
Its JavaScript optimiser needs Debian's Node.js modules (/usr/share/nodejs),
which a Node.js from elsewhere does not search."""
import os
import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = "emscripten libstb-dev libtinyexr-dev (tools/packages.sh: pathlab_web)"


class WebBuildError(RuntimeError):
    pass


def missing_tools() -> list:
    """What the web build needs that this machine lacks (empty when it has everything)."""
    return [tool for tool in ("em++", "node") if shutil.which(tool) is None]


def environment() -> dict:
    env = dict(os.environ)
    env["NODE_PATH"] = os.pathsep.join(p for p in ("/usr/share/nodejs", env.get("NODE_PATH", "")) if p)
    return env


def build_web(folder: Path, target: str = "pathlab") -> Path:
    """Configures the web preset in `folder` and builds `target`; returns its .js. Raises WebBuildError."""
    for step in (["cmake", "--preset", "web", "-B", str(folder)],
                 ["cmake", "--build", str(folder), "--target", target]):
        done = subprocess.run(step, cwd=ROOT, env=environment(), capture_output=True, text=True)
        if done.returncode != 0:
            raise WebBuildError(f"{' '.join(step)} failed (exit {done.returncode}):\n{(done.stdout + done.stderr)[-3000:]}")
    return folder / f"{target}.js"


def node_command(program: Path) -> list:
    """The command line that runs a web build's program under Node.js, as a native one runs."""
    return ["node", "--no-experimental-fetch", str(program)]
