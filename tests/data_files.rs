//! `#fopen`, `#read`, `#write`, `#fclose` on the real file system: a data file read back
//! as POV-Ray writes it, and hostile names, each a positioned error that writes nothing.

use std::path::{Path, PathBuf};

use penumbra::lang::{Diagnostic, LoadOptions, Loaded, load_scene};

/// A fresh folder per test, removed at the end.
struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Dir {
        let d = std::env::temp_dir().join(format!("penumbra-data-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        Dir(d)
    }

    fn file(&self, name: &str, text: &str) -> PathBuf {
        let p = self.0.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    /// Every file under the folder, for "nothing was written" checks.
    fn listing(&self) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(&self.0)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn load(scene: &Path, allow_write: Option<&Path>) -> Result<Loaded, Diagnostic> {
    let options = LoadOptions {
        allow_write: allow_write.map(Path::to_path_buf),
        ..LoadOptions::default()
    };
    load_scene(scene, &options)
}

/// The error's message and its line and column.
fn error(scene: &Path, allow_write: Option<&Path>) -> (String, usize, usize) {
    match load(scene, allow_write) {
        Ok(_) => panic!("{} loaded", scene.display()),
        Err(d) => (
            d.message.clone(),
            d.line().unwrap_or(0),
            d.column().unwrap_or(0),
        ),
    }
}

#[test]
fn a_written_file_reads_back_as_povray_wrote_it() {
    let scenes = Dir::new("roundtrip");
    let out = Dir::new("roundtrip-out");
    let scene = scenes.file(
        "s.pov",
        r#"#fopen F "data.txt" write
#write (F, "\"Testing 123\",", 5, ",", <1,2,3>, ",", 1/3, ",", 1e20, ",", -2.5, "\n")
#fclose F
#fopen F "data.txt" read
#read (F, S, A, V, B, C, D)
#debug concat(S, " ", str(A,0,6), " ", vstr(3, V, ",", 0, 3), " ", str(B,0,6), " ", str(C/1e19,0,3), " ", str(D,0,3), " ", str(defined(F),0,0), "\n")
"#,
    );
    let loaded = load(&scene, Some(&out.0)).unwrap();
    // POV-Ray 3.7 wrote exactly this for the same #write.
    let text = std::fs::read_to_string(out.0.join("data.txt")).unwrap();
    assert_eq!(text, "\"Testing 123\",5,<1,2,3> ,0.333333,1e+20,-2.5\n");
    assert_eq!(
        loaded.debug,
        "Testing 123 5.000000 1.000,2.000,3.000 0.333333 10.000 -2.500 0\n"
    );
}

#[test]
fn writing_needs_the_option_and_stays_in_its_folder() {
    let scenes = Dir::new("write");
    let out = Dir::new("write-out");
    let scene = scenes.file("s.pov", "#fopen F \"x.txt\" write\n#write (F, 1)\n");
    let (m, line, col) = error(&scene, None);
    assert!(
        m.starts_with("refused: writing \"x.txt\" needs --allow-write"),
        "{m}"
    );
    assert_eq!((line, col), (1, 10));
    assert_eq!(scenes.listing(), ["s.pov"]);
    for name in ["../x.txt", "/tmp/x.txt", "/dev/null", "a/../../x.txt"] {
        let scene = scenes.file(
            "s.pov",
            &format!("#fopen F \"{name}\" write\n#write (F, 1)\n"),
        );
        let (m, line, col) = error(&scene, Some(&out.0));
        assert!(m.starts_with("refused:"), "{name}: {m}");
        assert_eq!((line, col), (1, 10), "{name}");
    }
    assert!(out.listing().is_empty(), "{:?}", out.listing());
}

#[test]
fn reading_stays_in_the_allowed_folders() {
    let scenes = Dir::new("read");
    for name in ["/etc/passwd", "../../x", "../read/s.pov", "/dev/zero"] {
        let scene = scenes.file("s.pov", &format!("#fopen F \"{name}\" read\n"));
        let (m, line, col) = error(&scene, None);
        assert!(m.starts_with("refused: the data file"), "{name}: {m}");
        assert_eq!((line, col), (1, 10), "{name}");
    }
    let scene = scenes.file("s.pov", "#fopen F \"missing.txt\" read\n");
    let (m, _, _) = error(&scene, None);
    assert_eq!(m, "cannot find the data file \"missing.txt\"");
}

#[cfg(unix)]
#[test]
fn symbolic_links_out_of_the_folder_are_refused() {
    let scenes = Dir::new("links");
    let out = Dir::new("links-out");
    std::os::unix::fs::symlink("/etc/passwd", scenes.0.join("passwd.txt")).unwrap();
    let scene = scenes.file("s.pov", "#fopen F \"passwd.txt\" read\n");
    let (m, line, col) = error(&scene, None);
    assert!(m.contains("symbolic link"), "{m}");
    assert_eq!((line, col), (1, 10));
    // A link inside the write folder pointing out of it is not written through.
    let target = scenes.file("target.txt", "keep");
    std::os::unix::fs::symlink(&target, out.0.join("out.txt")).unwrap();
    let scene = scenes.file(
        "s.pov",
        "#fopen F \"out.txt\" write\n#write (F, 1)\n#fclose F\n",
    );
    let (m, _, _) = error(&scene, Some(&out.0));
    assert!(m.starts_with("refused:"), "{m}");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
}

#[test]
fn the_file_closes_with_its_last_value() {
    // POV-Ray 3.7 printed "1", then "0 3", then refused the third #read.
    let scenes = Dir::new("close");
    scenes.file("v.txt", "1, 2,\n3\n");
    let scene = scenes.file(
        "s.pov",
        "#fopen F \"v.txt\" read\n#read (F, A, B)\n#debug concat(str(defined(F),0,0), \"\\n\")\n#read (F, C)\n#debug concat(str(defined(F),0,0), \" \", str(C,0,0), \"\\n\")\n",
    );
    assert_eq!(load(&scene, None).unwrap().debug, "1\n0 3\n");
    let scene = scenes.file(
        "s.pov",
        "#fopen F \"v.txt\" read\n#read (F, A, B, C)\n#read (F, D)\n",
    );
    let (m, line, col) = error(&scene, None);
    assert_eq!((m.as_str(), line, col), ("`F` is not an open file", 3, 8));
}

#[test]
fn a_huge_file_and_bad_values_are_errors() {
    let scenes = Dir::new("huge");
    // Sparse: 1 GiB of length without the disk space.
    let big = std::fs::File::create(scenes.0.join("big.txt")).unwrap();
    big.set_len(1 << 30).unwrap();
    let scene = scenes.file("s.pov", "#fopen F \"big.txt\" read\n");
    let (m, line, _) = error(&scene, None);
    assert!(m.contains("larger than the limit"), "{m}");
    assert_eq!(line, 1);
    scenes.file("bad.txt", "1, 2, oops\n");
    let scene = scenes.file("s.pov", "#fopen F \"bad.txt\" read\n#read (F, A, B, C)\n");
    let (m, _, _) = error(&scene, None);
    assert_eq!(m, "expected a number in the data file, found `oops`");
    let scene = scenes.file("s.pov", "#write (G, 1)\n");
    let (m, line, col) = error(&scene, None);
    assert_eq!(m, "`G` is not an open file");
    assert_eq!((line, col), (1, 9));
}
