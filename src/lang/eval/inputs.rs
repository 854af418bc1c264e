//! What a scene was made from, hashed: the render job's key for "the same scene" (frames
//! that can keep their render-ready scene, shards and checkpoints that may be merged).
//!
//! The scene model is a pure function of its inputs: the scene text, every file it
//! reads (includes, images, fonts, data files), the `--declare` values, the image size
//! and, when the scene reads them, the animation identifiers. Hashing those costs a read
//! of each file; hashing the model itself (through its Debug form) took longer than the
//! render of a million spheres.

use std::cell::{Cell, RefCell};
use std::collections::BTreeSet;
use std::path::PathBuf;

use crate::lang::{LoadOptions, SourceFiles};
use crate::output::Fnv;

/// The files a scene read (sorted, so the hash does not depend on a set's order), and
/// whether it read the animation clock.
#[derive(Default)]
pub struct Inputs {
    files: RefCell<BTreeSet<PathBuf>>,
    pub read_clock: Cell<bool>,
}

impl Inputs {
    /// Notes a file the scene reads (or asks about).
    pub fn file(&self, path: &std::path::Path) {
        let mut files = self.files.borrow_mut();
        if !files.contains(path) {
            files.insert(path.to_path_buf());
        }
    }

    /// The hash of the scene's inputs. File contents, not names: a farm's machines may
    /// keep POV-Ray's includes in different folders. A file that cannot be read again
    /// hashes as its name (the scene read it, so this is rare).
    pub fn hash(
        &self,
        source: &str,
        options: &LoadOptions,
        skip_unsupported: bool,
        sources: &dyn SourceFiles,
    ) -> u64 {
        let mut h = Fnv::default();
        h.write_field(env!("CARGO_PKG_VERSION").as_bytes());
        h.write_field(&[u8::from(skip_unsupported)]);
        h.write_field(source.as_bytes());
        for path in self.files.borrow().iter() {
            match std::fs::read(path) {
                Ok(bytes) => h.write_field(&bytes),
                Err(_) => match sources.read(path) {
                    Ok(text) => h.write_field(text.as_bytes()),
                    Err(_) => h.write_field(path.display().to_string().as_bytes()),
                },
            }
        }
        for (name, value) in &options.declares {
            h.write_field(name.as_bytes());
            h.write_field(&value.to_bits().to_le_bytes());
        }
        h.write_field(&options.image_width.to_le_bytes());
        h.write_field(&options.image_height.to_le_bytes());
        if self.read_clock.get() {
            let c = &options.clock;
            for x in [c.clock, c.clock_delta, c.initial_clock, c.final_clock] {
                h.write_field(&x.to_bits().to_le_bytes());
            }
            for n in [c.frame_number, c.initial_frame, c.final_frame] {
                h.write_field(&n.to_le_bytes());
            }
            h.write_field(&[u8::from(c.clock_on)]);
        }
        h.finish()
    }
}
