//! Tests of the sliced parse: the same scene as the one-go load, in many slices, and the same
//! error line for a bad file.

use super::*;

/// A generated sphere parses in slices (the container, the buffers, each array of its one
/// primitive, the object) into the scene `load_scene` reads from the same file.
#[test]
fn a_sliced_parse_gives_the_scene_of_the_one_go_load() {
    let dir = std::env::temp_dir().join(format!("shadelab-slices-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("sphere.glb");
    std::fs::write(&path, synthetic::sphere_glb(2_000, true).0).unwrap();
    let mut parse = SceneParse::new(ParseSource::Path(path.clone(), false));
    let sliced = loop {
        if let Some(r) = parse.step() {
            break r.unwrap();
        }
    };
    // The container and its JSON, the buffers, then a slice per array of the primitive
    // (positions, normals, morph targets, uvs, colours, tangents, indices, triangles, the mesh,
    // generated tangents) and the object's: at least 12.
    assert!(parse.slices() >= 12, "{} slices", parse.slices());
    assert!(parse.step().is_none(), "a step after the answer answers nothing");
    let whole = load_scene(&path).unwrap();
    assert_same_scene(&whole.scene, &sliced.scene);
    assert_eq!(whole.warnings, sliced.warnings);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A broken file handed in by name fails in its first slice with the one-go load's line.
#[test]
fn a_sliced_parse_of_a_bad_file_gives_the_same_line() {
    let files = vec![("bad.glb".to_string(), b"glTF\x02\0\0\0\xff\xff\0\0".to_vec())];
    let whole = load_scene_from_files("bad.glb", &files).unwrap_err().to_string();
    let source = ParseSource::from_files(files).unwrap();
    assert_eq!(source.name(), "bad.glb");
    let mut parse = SceneParse::new(source);
    let sliced = parse.step().expect("an answer in the first slice").unwrap_err().to_string();
    assert_eq!(sliced, whole);
    assert!(whole.starts_with("bad.glb: truncated GLB"), "{whole}");
}

/// Files without a scene file among them are named in one line.
#[test]
fn files_without_a_scene_file_are_refused() {
    let e = ParseSource::from_files(vec![("a.bin".into(), vec![]), ("b.png".into(), vec![])]).err().unwrap();
    assert_eq!(e, "no .gltf or .glb file among the files given: a.bin, b.png");
}
