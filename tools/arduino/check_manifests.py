#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""arduino_manifests: the Arduino (library.properties, 1.5 format) and
PlatformIO (library.json) manifests at the top of the tree are valid and
agree with each other and with core/include/zline/zl_version.h.

  tools/arduino/check_manifests.py [SOURCE_DIR]   check the tree (default: this one)
  tools/arduino/check_manifests.py --self-test    the check must fail on broken copies

Prints each problem; exits with their count (0: valid)."""
import json
import os
import re
import shutil
import sys
import tempfile

# library.properties keys the Arduino library specification (1.5 format)
# requires, and its list of categories.
PROPERTIES_REQUIRED = ["name", "version", "author", "maintainer", "sentence", "paragraph",
                       "category", "url", "architectures"]
ARDUINO_CATEGORIES = ["Display", "Communication", "Signal Input/Output", "Sensors", "Device Control",
                      "Timing", "Data Storage", "Data Processing", "Other"]
SEMVER = re.compile(r"^[0-9]+\.[0-9]+\.[0-9]+$")
EXAMPLES_DIR = os.path.join("port", "arduino", "examples")  # examples/ in the library


def read_properties(path):
    """key=value lines; '#' lines are comments."""
    props = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            if "=" not in line:
                raise ValueError(f"line {number} is not key=value: {line!r}")
            key, value = line.split("=", 1)
            props[key.strip()] = value.strip()
    return props


def header_version(path):
    parts = {}
    with open(path, encoding="utf-8") as f:
        for m in re.finditer(r"#define ZL_VERSION_(MAJOR|MINOR|PATCH) ([0-9]+)", f.read()):
            parts[m.group(1)] = m.group(2)
    if len(parts) != 3:
        raise ValueError(f"{path}: no ZL_VERSION_MAJOR/MINOR/PATCH")
    return "{MAJOR}.{MINOR}.{PATCH}".format(**parts)


def check_properties(props, problems):
    for key in PROPERTIES_REQUIRED:
        if not props.get(key):
            problems.append(f"library.properties: required key '{key}' missing or empty")
    if props.get("category") and props["category"] not in ARDUINO_CATEGORIES:
        problems.append(f"library.properties: category '{props['category']}' is not an Arduino category")
    if props.get("version") and not SEMVER.match(props["version"]):
        problems.append(f"library.properties: version '{props['version']}' is not MAJOR.MINOR.PATCH")
    if props.get("url") and not props["url"].startswith("https://"):
        problems.append("library.properties: url is not an https:// address")
    for header in filter(None, props.get("includes", "").split(",")):
        if header.strip() not in ("zline.h", "zl_spi_panel.h"):
            problems.append(f"library.properties: includes names '{header}', not a header of the library's src/")


def check_json(top, manifest, problems):
    for key in ("name", "version", "description", "keywords", "repository", "license", "frameworks",
                "platforms"):
        if key not in manifest:
            problems.append(f"library.json: required field '{key}' missing")
    if manifest.get("license") != "MIT":
        problems.append(f"library.json: license is {manifest.get('license')!r}, not MIT (LICENSE)")
    if not SEMVER.match(str(manifest.get("version", ""))):
        problems.append(f"library.json: version {manifest.get('version')!r} is not MAJOR.MINOR.PATCH")
    for example in manifest.get("examples", []):
        base = example.get("base", "")
        if not base.startswith("examples/"):
            problems.append(f"library.json: example base {base!r} is not under examples/")
            continue
        for name in example.get("files", []):
            if not os.path.isfile(os.path.join(top, EXAMPLES_DIR, base[len("examples/"):], name)):
                problems.append(f"library.json: example file {base}/{name} is not in {EXAMPLES_DIR}")


def check(top):
    problems = []
    try:
        props = read_properties(os.path.join(top, "library.properties"))
        with open(os.path.join(top, "library.json"), encoding="utf-8") as f:
            manifest = json.load(f)
        version = header_version(os.path.join(top, "core", "include", "zline", "zl_version.h"))
    except (OSError, ValueError) as e:  # json.JSONDecodeError is a ValueError
        return [f"cannot read the manifests: {e}"]
    check_properties(props, problems)
    check_json(top, manifest, problems)
    if props.get("name") != "zline" or manifest.get("name") != "zline":
        problems.append(f"names: library.properties {props.get('name')!r}, library.json "
                        f"{manifest.get('name')!r}, not both 'zline'")
    for what, value in (("library.properties", props.get("version")), ("library.json", manifest.get("version"))):
        if value != version:
            problems.append(f"{what}: version {value!r}, zl_version.h says {version}")
    json_url = manifest.get("repository", {}).get("url") if isinstance(manifest.get("repository"), dict) else None
    if props.get("url") != json_url:
        problems.append(f"url: library.properties {props.get('url')!r}, library.json {json_url!r}")
    return problems


def self_test(top):
    """Each broken copy must fail the check; the unbroken copy must pass
    unless the tree itself fails."""
    breakages = {
        "library.json not JSON": ("library.json", lambda t: t.replace("{", "[", 1)),
        "library.json version differs": ("library.json", lambda t: re.sub(r'"version": "[^"]*"', '"version": "9.9.9"', t)),
        "library.properties version differs": ("library.properties", lambda t: re.sub(r"(?m)^version=.*$", "version=9.9.9", t)),
        "library.properties without sentence": ("library.properties", lambda t: re.sub(r"(?m)^sentence=.*\n", "", t)),
        "zl_version.h differs": (os.path.join("core", "include", "zline", "zl_version.h"),
                                 lambda t: re.sub(r"ZL_VERSION_PATCH [0-9]+", "ZL_VERSION_PATCH 99", t)),
    }
    failures = 0
    for what, (name, breakage) in breakages.items():
        with tempfile.TemporaryDirectory() as tmp:
            for rel in ("library.properties", "library.json", os.path.join("core", "include", "zline", "zl_version.h")):
                os.makedirs(os.path.dirname(os.path.join(tmp, rel)), exist_ok=True)
                shutil.copy(os.path.join(top, rel), os.path.join(tmp, rel))
            shutil.copytree(os.path.join(top, EXAMPLES_DIR), os.path.join(tmp, EXAMPLES_DIR))
            path = os.path.join(tmp, name)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            broken = breakage(text)
            if broken == text:
                print(f"arduino_manifests self-test: could not apply '{what}'")
                failures += 1
                continue
            with open(path, "w", encoding="utf-8") as f:
                f.write(broken)
            if not check(tmp):
                print(f"arduino_manifests self-test: '{what}' passed the check")
                failures += 1
    print(f"arduino_manifests self-test: {len(breakages) - failures} of {len(breakages)} broken copies fail the check")
    return failures


def main():
    here = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    if sys.argv[1:] == ["--self-test"]:
        return self_test(here)
    top = sys.argv[1] if len(sys.argv) > 1 else here
    problems = check(top)
    for p in problems:
        print(f"arduino_manifests: {p}")
    if not problems:
        print("arduino_manifests: library.properties and library.json valid, version "
              f"{read_properties(os.path.join(top, 'library.properties'))['version']} as in zl_version.h")
    return len(problems)


if __name__ == "__main__":
    sys.exit(main())
