#!/usr/bin/python3
"""Every shader program the testbed builds, compiled by Khronos' reference GLSL front-end
(glslangValidator, Debian's glslang-tools) as well as by Mesa: no errors, no warnings.

Mesa is the only compiler the suite otherwise meets, and NVIDIA's and AMD's accept and
reject different things; glslang follows the GLSL 4.50 specification to the letter, so a
source it accepts is far more likely to compile on every driver (docs/portability.md).

The sources are the ones the GL really receives: the testbed runs with TESTBED_SHADER_DUMP
set (testbed/gl/shader_library.h), which writes each stage's final text, includes expanded
and defines in, once per distinct text. The runs cover every technique (the bundled ones and
the two example plugins) at both paths (`--path fast|paper`), every depth format, and every
parameter value that can change a define: each choice and bool value, and each int
parameter at its minimum and its maximum (a kernel or blur radius sizes loops and arrays;
both ends keep the parity some insist on), taken from
`testbed list --json` so a new parameter is covered without editing this file. The ground
truth (shadow volumes, area-light reference) and the G-buffer and shadow-map passes run in
every `compare`. The viewer's only shaders of its own are Dear ImGui's OpenGL 3 backend's,
compiled with "#version 450" (testbed/viewer/viewer.cpp); they are read from the backend
source Debian ships and checked too.

usage: glslang_portability_test.py TESTBED_BINARY OUTPUT_FOLDER [PLUGIN_LIBRARY]...
"""
import json
import os
import re
import shutil
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
TESTBED, OUT = sys.argv[1], os.path.abspath(sys.argv[2])
PLUGINS = sys.argv[3:]
GLSLANG = shutil.which("glslangValidator")
IMGUI_BACKEND = "/usr/share/doc/libimgui-dev/examples/backends/imgui_impl_opengl3.cpp"
SCENE = os.path.join(REPO, "scenes", "wall.json")
# Tiny frames: the point is which programs are built, not what they draw.
FRAME = ["--size", "64x36", "--shadow-map", "64"]


def plugin_arguments():
    return [argument for plugin in PLUGINS for argument in ("--plugin", plugin)]


def run_testbed(arguments, environment=None):
    run = subprocess.run([TESTBED, *arguments], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                         env=environment)
    if run.returncode != 0:
        raise AssertionError(f"testbed {' '.join(arguments)} failed ({run.returncode}):\n{run.stderr}")
    return run.stdout


def non_default_values(parameter):
    """The values of one parameter worth a build of their own (see the module comment)."""
    kind = parameter["type"]
    if kind == "choice":
        values = parameter["choices"]
    elif kind == "bool":
        values = [True, False]
    elif kind == "int":
        values = [int(parameter["min"]), int(parameter["max"])]
    else:  # float parameters are uniforms: they never reach a define
        return []
    default = parameter["default"]
    return [value for value in values if str(value).lower() != str(default).lower()]


def variant_rounds(techniques):
    """Lists of `--set T.k=v`: round i sets the i-th non-default value of every technique that
    has one, so one `compare` covers a value of every technique at once."""
    per_technique = {}
    for technique in techniques:
        settings = []
        for parameter in technique["parameters"]:
            for value in non_default_values(parameter):
                text = str(value).lower() if isinstance(value, bool) else str(value)
                settings.append(f"{technique['id']}.{parameter['name']}={text}")
        per_technique[technique["id"]] = settings
    rounds = max(len(settings) for settings in per_technique.values())
    return [[settings[i] for settings in per_technique.values() if i < len(settings)] for i in range(rounds)]


def round_arguments(settings):
    """`compare` arguments for one round: only the techniques it sets (`sm` always runs)."""
    techniques = sorted({setting.split(".")[0] for setting in settings})
    return ["--techniques", ",".join(techniques), *[a for s in settings for a in ("--set", s)]]


def imgui_sources():
    """Dear ImGui's GLSL 4.10-core vertex and fragment shaders, which its backend picks for
    "#version 450" and prefixes with that line."""
    with open(IMGUI_BACKEND, encoding="utf-8") as file:
        code = file.read()
    sources = {}
    for stage, name in (("vert", "vertex_shader_glsl_410_core"), ("frag", "fragment_shader_glsl_410_core")):
        match = re.search(r"const GLchar\*\s*" + name + r"\s*=\s*((?:\s*\"(?:[^\"\\]|\\.)*\")+)\s*;", code)
        if not match:
            raise AssertionError(f"{IMGUI_BACKEND}: {name} not found (Dear ImGui changed its backend?)")
        pieces = re.findall(r"\"((?:[^\"\\]|\\.)*)\"", match.group(1))
        text = "".join(pieces).encode().decode("unicode_escape")
        sources[f"imgui_impl_opengl3.{stage}"] = "#version 450\n" + text
    return sources


def fnv1a_hex(data):
    """FNV-1a, 64 bits, as 16 hex digits: the dump's file-name hash."""
    value = 0xcbf29ce484222325
    for byte in data:
        value = ((value ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{value:016x}"


def glslang(path):
    """glslangValidator's verdict on one stage (stage from the extension), GLSL for OpenGL:
    (exit status, its messages)."""
    run = subprocess.run([GLSLANG, path], capture_output=True, text=True)
    # It prints the file's name first; what follows are its messages.
    messages = [line for line in run.stdout.splitlines() + run.stderr.splitlines()
                if line.strip() and line.strip() != path]
    return run.returncode, messages


class GlslangPortability(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if GLSLANG is None:
            raise AssertionError("glslangValidator is missing: install glslang-tools (scripts/setup.sh does)")
        shutil.rmtree(OUT, ignore_errors=True)
        cls.dump = os.path.join(OUT, "shaders")
        os.makedirs(cls.dump)
        environment = dict(os.environ, TESTBED_SHADER_DUMP=cls.dump)
        techniques = json.loads(run_testbed(["list", "--json", *plugin_arguments()]))
        cls.technique_ids = [technique["id"] for technique in techniques]
        runs = []
        for path in ("fast", "paper"):
            # The area-light reference too, and every technique at its defaults.
            runs.append(["--path", path, "--techniques", "all", "--reference", "both", "--area-samples", "2"])
            # Only a float depth buffer changes a define (the shadow-map pass's offset).
            runs.append(["--path", path, "--techniques", "all", "--depth-format", "32f"])
            runs += [["--path", path, *round_arguments(settings)] for settings in variant_rounds(techniques)]
        for number, extra in enumerate(runs):
            run_testbed(["compare", "--scene", SCENE, *FRAME, *plugin_arguments(), *extra,
                         "--out", os.path.join(OUT, "runs", str(number))], environment)
        for name, text in imgui_sources().items():
            with open(os.path.join(cls.dump, name), "w", encoding="utf-8") as file:
                file.write(text)
        cls.sources = sorted(os.listdir(cls.dump))

    def test_every_technique_and_pass_was_dumped(self):
        keys = {name.split(".")[0] for name in self.sources}
        for expected in ("groundtruth_shadow_volume", "groundtruth_volume_visibility", "testbed_render_gbuffer",
                         "testbed_render_shadow_map", "testbed_render_fullscreen", "imgui_impl_opengl3",
                         "tests_plugin_example_example_sm", "tests_plugin_example_pcss"):
            self.assertIn(expected, keys)
        folders = {key.split("_")[0] for key in keys}
        self.assertIn("techniques", folders)
        # One file per distinct text: the hash in each name is its text's.
        for name in self.sources:
            if name.startswith("imgui_impl_opengl3."):
                continue
            with open(os.path.join(self.dump, name), "rb") as file:
                self.assertEqual(name.split(".")[-2], fnv1a_hex(file.read()), name)

    def test_glslang_finds_no_error_and_no_warning(self):
        failures = []
        for name in self.sources:
            status, messages = glslang(os.path.join(self.dump, name))
            if status != 0 or messages:
                failures.append(f"{name} (exit {status}):\n  " + "\n  ".join(messages))
        self.assertEqual(failures, [], f"{len(failures)} of {len(self.sources)} sources:\n" + "\n".join(failures))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
