"""The lucent Python module against the lucent command and against physics.

Run from CTest (Python.Module) with PYTHONPATH at build/python, LUCENT_BINARY
the lucent command and LUCENT_SOURCE_DIR the source tree.
"""
import os
import shutil
import subprocess
import threading
from pathlib import Path

import numpy as np
import pytest

import lucent

SOURCE = Path(os.environ["LUCENT_SOURCE_DIR"])
BINARY = os.environ["LUCENT_BINARY"]


def read_pfm(path):
    """A colour PFM as float32 rows from the top (PFM stores them from the bottom)."""
    data = Path(path).read_bytes()
    header, rest = data.split(b"\n", 1)
    assert header == b"PF"
    size, rest = rest.split(b"\n", 1)
    width, height = map(int, size.split())
    scale, rest = rest.split(b"\n", 1)
    dtype = "<f4" if float(scale) < 0 else ">f4"
    pixels = np.frombuffer(rest, dtype=dtype, count=width * height * 3).reshape(height, width, 3)
    return pixels[::-1].astype(np.float32)


def sphere_scene(folder):
    """The bundled sphere scene, copied so that sample files land in folder."""
    shutil.copy(SOURCE / "models" / "sphere.obj", folder / "sphere.obj")
    text = (SOURCE / "models" / "sphere.json").read_text()
    (folder / "sphere.json").write_text(text)
    return folder / "sphere.json"


def test_an_image_from_python_equals_the_commands_pfm_byte_for_byte(tmp_path):
    scene_file = sphere_scene(tmp_path)
    out = tmp_path / "command.pfm"
    subprocess.run([BINARY, "render", str(scene_file), "--method", "reference", "--width", "24", "--height", "16",
                    "-o", str(out)], check=True, capture_output=True)
    image, report = lucent.render(lucent.load_scene(str(scene_file)), method="reference", width=24, height=16)
    assert image.dtype == np.float32 and image.shape == (16, 24, 3)
    assert report["method"] == "reference"
    assert image.max() > 0
    assert image.tobytes() == read_pfm(out).tobytes()


def test_edits_to_a_scene_take_effect(tmp_path):
    scene = lucent.load_scene(str(sphere_scene(tmp_path)))
    before, _ = lucent.render(scene, method="reference", width=12, height=12)
    # Radiance is linear in every light's intensity: doubling all doubles the image.
    for light in scene.lights:
        light.intensity = tuple(2 * x for x in light.intensity)
    doubled, _ = lucent.render(scene, method="reference", width=12, height=12)
    np.testing.assert_allclose(doubled, 2 * before, rtol=1e-5, atol=1e-7)
    # Single scattering is linear in the albedo too.
    scene.objects[0].albedo = tuple(0.5 * a for a in scene.objects[0].albedo)
    halved, _ = lucent.render(scene, method="reference", width=12, height=12)
    np.testing.assert_allclose(halved, before, rtol=1e-5, atol=1e-7)
    scene.camera.width = 7
    assert lucent.render(scene, method="reference", height=5)[0].shape == (5, 7, 3)


def test_errors_arrive_as_exceptions_with_the_commands_line(tmp_path):
    with pytest.raises(lucent.Error, match="missing.json: cannot open scene file"):
        lucent.load_scene(str(tmp_path / "missing.json"))
    scene = lucent.load_scene(str(sphere_scene(tmp_path)))
    with pytest.raises(lucent.Error, match="unknown method|not built|valid"):
        lucent.render(scene, method="nonsense")
    with pytest.raises(ValueError):
        scene.objects[0].albedo = (0.5, float("nan"), 0.5)
    with pytest.raises(ValueError):
        scene.objects[0].ior = 0.5
    # A new sigma_t asks for new samples: the old sample file is refused, not drawn.
    lucent.preprocess(scene, quality="draft")
    scene.objects[0].sigma_t = (9.0, 9.0, 9.0)
    with pytest.raises(lucent.Error, match="run lucent preprocess again"):
        lucent.render(scene, method="ss", width=8, height=8)


def test_preprocess_then_a_sample_method_with_progress(tmp_path):
    scene = lucent.load_scene(str(sphere_scene(tmp_path)))
    made = lucent.preprocess(scene, quality="draft")
    assert made[0]["samples"] > 0 and Path(made[0]["file"]).is_file()
    stages = []
    image, report = lucent.render(scene, method="ss", width=16, height=16, options={"light": "sh"},
                                  progress=lambda stage, fraction: stages.append((stage, fraction)))
    assert report["method"] == "ss" and image.max() > 0
    assert all(0.0 <= f <= 1.0 for _, f in stages)


def test_two_renders_in_threads_give_what_one_gives(tmp_path):
    scene = lucent.load_scene(str(sphere_scene(tmp_path)))
    alone, _ = lucent.render(scene, method="reference", width=10, height=10)
    results = [None, None]

    def work(i):
        results[i] = lucent.render(scene, method="reference", width=10, height=10)[0]

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        assert r.tobytes() == alone.tobytes()


def test_a_blender_export_loads_and_renders(tmp_path):
    model = tmp_path / "jade.glb"
    shutil.copy(SOURCE / "tests" / "data" / "gltf" / "blender-cube.glb", model)
    scene = lucent.load_scene(str(model), camera="View")
    assert [o.name for o in scene.objects] == ["Jade"]
    assert any("absorbs and does not scatter" in w for w in scene.warnings)
    assert Path(scene.objects[0].samples).name == "jade.Jade.lsf"
    scene.objects[0].albedo = (0.8, 0.8, 0.8)  # scattering, so that the image is not black
    image, report = lucent.render(scene, method="reference", width=8, height=8)
    assert image.max() > 0


def test_methods_and_presets_describe_this_build():
    names = [m["name"] for m in lucent.methods()]
    assert "reference" in names and "path" in names and "ss" in names
    path = next(m for m in lucent.methods() if m["name"] == "path")
    assert any(o["name"] == "samples" for o in path["options"])
    presets = {p["name"]: p for p in lucent.presets()}
    assert "marble" in presets or "skin1" in presets
    for p in presets.values():
        assert all(0.0 <= a <= 1.0 for a in p["albedo"])


def test_progress_of_long_work_goes_to_the_callback_or_to_tqdm(tmp_path, capfd):
    scene = lucent.load_scene(str(sphere_scene(tmp_path)))
    # Long enough (over a second) for Progress to report.
    long = dict(method="path", width=64, height=64, options={"samples": 1024})
    stages = []
    lucent.render(scene, progress=lambda stage, fraction: stages.append((stage, fraction)), **long)
    assert stages and stages[-1] == ("path tracing", 1.0)
    assert all(0.0 <= f <= 1.0 for _, f in stages)
    capfd.readouterr()
    lucent.render(scene, **long)  # no callback: a tqdm bar, tqdm being installed
    assert "path tracing" in capfd.readouterr().err
