"""pip install . (pyproject.toml): builds the CMake target proxyvis_python (apps/python) and puts
the module and its stub proxyvis.pyi in the wheel. The CMake build folder is build/ beside this
file (PROXYVIS_BUILD_DIR chooses another), configured as ./setup.sh configures it when it is not
yet; an existing one is reused, so after ./setup.sh build only the module is linked again.
PROXYVIS_JOBS sets the build's jobs (default: all cores)."""
import glob
import os
import re
import shutil
import subprocess

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def version():
    text = open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8").read()
    return re.search(r"project\(proxyvis VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.path.abspath(os.environ.get("PROXYVIS_BUILD_DIR", os.path.join(ROOT, "build")))
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, "-G", "Ninja",
                            "-DCMAKE_BUILD_TYPE=Release"], check=True)
        jobs = os.environ.get("PROXYVIS_JOBS", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", build_dir, "-j", jobs, "--target", "proxyvis_python"],
                       check=True)
        built = glob.glob(os.path.join(build_dir, "python", "proxyvis.*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one module in {build_dir}/python, found {built} "
                               "(is pybind11-dev installed? ./setup.sh installs it)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        shutil.copyfile(os.path.join(build_dir, "python", "proxyvis.pyi"),
                        os.path.join(os.path.dirname(target), "proxyvis.pyi"))


setup(
    version=version(),
    ext_modules=[Extension("proxyvis", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build folder inside CMake's, not the CMake tree itself.
    options={"build": {"build_base": os.path.join("build", "setuptools")},
             "egg_info": {"egg_base": os.path.join("build", "setuptools")}},
)
