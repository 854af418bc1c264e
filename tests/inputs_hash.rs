//! The inputs hash is the render job's key for "the same scene": equal exactly when the
//! scene text, the files it read and the options it saw are equal.

use std::path::PathBuf;

use penumbra::lang::{AnimationClock, LoadOptions, MemoryFiles, load_with_files};

const SCENE: &str = "#include \"part.inc\"\nsphere { 0, R pigment { rgb 1 } }\n";

fn files(part: &str) -> MemoryFiles {
    let mut f = MemoryFiles::default();
    f.files.insert(PathBuf::from("part.inc"), part.to_string());
    f
}

fn hash(source: &str, files: &MemoryFiles, options: &LoadOptions) -> u64 {
    load_with_files("scene.pov", source, options, files)
        .expect("loads")
        .inputs_hash
}

fn frame(n: i64) -> LoadOptions {
    LoadOptions {
        clock: AnimationClock {
            frame_number: n,
            clock: n as f64 / 10.0,
            ..AnimationClock::default()
        },
        ..LoadOptions::default()
    }
}

#[test]
fn equal_inputs_hash_equal_and_a_changed_include_does_not() {
    let base = LoadOptions::default();
    let a = hash(SCENE, &files("#declare R = 1;"), &base);
    assert_eq!(a, hash(SCENE, &files("#declare R = 1;"), &base));
    assert_ne!(a, hash(SCENE, &files("#declare R = 2;"), &base));
    let edited = SCENE.replace("rgb 1", "rgb 0.5");
    assert_ne!(a, hash(&edited, &files("#declare R = 1;"), &base));
    let declared = LoadOptions {
        declares: vec![("Q".into(), 1.0)],
        ..LoadOptions::default()
    };
    assert_ne!(a, hash(SCENE, &files("#declare R = 1;"), &declared));
}

#[test]
fn the_clock_counts_only_when_the_scene_reads_it() {
    let still = files("#declare R = 1;");
    assert_eq!(
        hash(SCENE, &still, &frame(1)),
        hash(SCENE, &still, &frame(2))
    );
    let moving = files("#declare R = 1 + clock;");
    assert_ne!(
        hash(SCENE, &moving, &frame(1)),
        hash(SCENE, &moving, &frame(2))
    );
}
