"""Maps the repository's top-level folders into the ``kinefuse`` namespace.

codegen/ -> kinefuse.codegen, host/ -> kinefuse.host, firmware/ -> kinefuse.firmware,
hil_tests/ -> kinefuse.hil_tests.  Nothing with a generic name lands in site-packages.
Everything else lives in pyproject.toml.
"""
from setuptools import find_packages, setup

ROOTS = {"codegen": "kinefuse.codegen", "host": "kinefuse.host",
         "firmware": "kinefuse.firmware", "hil_tests": "kinefuse.hil_tests"}

packages, package_dir = [], {}
for folder, name in ROOTS.items():
    package_dir[name] = folder
    packages.append(name)
    packages += [f"{name}.{sub}" for sub in find_packages(folder, exclude=["tests", "tests.*"])]

setup(
    packages=packages,
    package_dir=package_dir,
    # generated C, dialect XML, bundled sample data and plugin sources ship with the package
    package_data={"": ["*.c", "*.h", "*.ld", "*.xml", "*.npz", "*.json", "*.md", "*.txt", "*.csv", "Makefile"]},
)
