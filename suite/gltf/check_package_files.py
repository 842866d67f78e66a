#!/usr/bin/python3
"""Every glTF 2.0 file of Debian's assimp-testmodels package through the importer.

Each file is read as a bare glTF scene (`lightcts lights --scene FILE`):
  - the real models must load (exit 0); the warnings they print must name
    what was ignored;
  - the deliberately broken ones whose fault reaches the model must exit 2
    with a message that names the file and the glTF JSON path;
  - the ones whose fault lies only in what the model ignores (a texture
    reference, a name) may exit 2 or load with a warning naming the fault.
A file of the package this table does not list is a failure too, so a new
package version is looked at, not skipped. Never a crash, never silence.

Usage: check_package_files.py LIGHTCTS [MODELS_DIR]
Exit status: 0 all as expected, 1 otherwise, 3 the package is not installed.
"""
import os
import subprocess
import sys

MODELS = "/usr/share/assimp/models/glTF2"

# file -> (expectation, text the message must hold: a JSON path)
#   load:  exit 0
#   error: exit 2, stderr names the file and the path
#   warn:  exit 0 with a warning holding the path, or exit 2 holding it
EXPECTED = {
    # real content
    "2CylinderEngine-glTF-Binary/2CylinderEngine.glb": ("load", None),
    "BoxBadNormals-glTF-Binary/BoxBadNormals.glb": ("load", "/attributes/NORMAL"),
    "BoxTexcoords-glTF/boxTexcoords.gltf": ("load", None),
    "BoxTextured-glTF/BoxTextured.gltf": ("load", None),
    "BoxTextured-glTF-Binary/BoxTextured.glb": ("load", None),
    "BoxTextured-glTF-Embedded/BoxTextured.gltf": ("load", None),
    "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf": ("load", "/extensionsUsed/0"),
    "ClearCoat-glTF/ClearCoatTest.gltf": ("load", None),
    "cameras/Cameras.gltf": ("load", None),
    "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf": ("load", None),
    "simple_skin/simple_skin.gltf": ("load", "/skin"),
    "textureTransform/TextureTransformTest.gltf": ("load", None),
    "issue_3269/texcoord_crash.gltf": ("load", None),
    "TestNoRootNode/SceneWithoutNodes.gltf": ("load", "/scenes/0"),
    # broken where the model reads
    "IndexOutOfRange/IndexOutOfRange.gltf": ("error", "/accessors/"),
    "IndexOutOfRange/AllIndicesOutOfRange.gltf": ("error", "/accessors/"),
    "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb": ("error", "/accessors/"),
    "wrongTypes/badArray.gltf": ("error", "/meshes/0/primitives"),
    "wrongTypes/badObject.gltf": ("error", "/materials/0/pbrMetallicRoughness"),
    "MissingBin/BoxTextured.gltf": ("error", "/buffers/0"),
    "RecursiveNodes/RecursiveNodes.gltf": ("error", "/nodes/"),
    "SchemaFailures/sceneWrongType.gltf": ("error", "/scene"),
    "TestNoRootNode/NoScene.gltf": ("error", "/scene"),
    "IncorrectVertexArrays/Cube.gltf": ("error", "/meshes/1/primitives/0"),
    # extensions the file requires and lightcts does not read
    "draco/2CylinderEngine.gltf": ("error", "/extensionsRequired/"),
    "BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf": ("error", "/extensionsRequired/0"),
    # broken only in what the model ignores
    "wrongTypes/badString.gltf": ("warn", "/scenes/0/name"),
    "wrongTypes/badUint.gltf": ("warn", "/baseColorTexture/index"),
    "wrongTypes/badNumber.gltf": ("warn", "/materials/0/normalTexture"),
    "wrongTypes/badExtension.gltf": ("warn", "/extensions/KHR_texture_transform"),
}
# The asset generator's primitive modes: triangles load; points and lines
# load with a warning that they were skipped.
for n in range(16):
    name = f"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_{n:02d}.gltf"
    EXPECTED[name] = ("load", "/mode" if n in (0, 1, 2, 3, 7, 8, 9, 10) else None)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    lightcts = sys.argv[1]
    models = sys.argv[2] if len(sys.argv) > 2 else MODELS
    if not os.path.isdir(models):
        print(f"NotSupported: {models} is missing (Debian's assimp-testmodels; scripts/setup.sh installs it)")
        return 3
    found = set()
    for root, _, files in os.walk(models):
        for f in files:
            if f.endswith((".gltf", ".glb")):
                found.add(os.path.relpath(os.path.join(root, f), models))
    failures = []
    for name in sorted(found - set(EXPECTED)):
        failures.append(f"{name}: a file of the package that the table does not list")
    for name, (expect, path) in sorted(EXPECTED.items()):
        full = os.path.join(models, name)
        if name not in found:
            failures.append(f"{name}: listed but not in the package")
            continue
        run = subprocess.run([lightcts, "lights", "--scene", full], capture_output=True, text=True, timeout=300)
        err = run.stderr
        first = (err.strip().splitlines() or [""])[0]
        verdict = f"exit {run.returncode}: {first[:300]}"
        ok = True
        if expect == "load":
            ok = run.returncode == 0 and (path is None or path in err)
        elif expect == "error":
            ok = run.returncode == 2 and os.path.basename(name) in err and path in err
        elif expect == "warn":
            ok = run.returncode in (0, 2) and os.path.basename(name) in err and path in err
        print(f"{'ok  ' if ok else 'FAIL'} {expect:5} {name}: {verdict}")
        if not ok:
            failures.append(f"{name}: expected {expect} naming {path!r}, got exit {run.returncode}\n{err}")
    for f in failures:
        print("FAIL", f)
    print(f"{len(EXPECTED)} files, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
