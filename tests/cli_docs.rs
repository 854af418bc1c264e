//! docs/cli.md lists every POV-Ray switch and INI key from the one option table
//! (src/povray_args/table.rs) that the parser reads. `PENUMBRA_WRITE_DOCS=1 cargo test
//! --release --test cli_docs` rewrites the generated part.

use std::path::PathBuf;

const BEGIN: &str = "<!-- options table: generated from src/povray_args/table.rs -->\n";
const END: &str = "<!-- end of options table -->";

#[test]
fn docs_cli_md_holds_the_option_table() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs/cli.md");
    let text = std::fs::read_to_string(&path).expect("docs/cli.md");
    let start = text.find(BEGIN).expect("begin marker") + BEGIN.len();
    let end = text.find(END).expect("end marker");
    let table = penumbra::povray_args::table::markdown_table();
    if std::env::var_os("PENUMBRA_WRITE_DOCS").is_some() {
        let new = format!("{}{table}{}", &text[..start], &text[end..]);
        std::fs::write(&path, new).expect("writes docs/cli.md");
        return;
    }
    assert_eq!(
        &text[start..end],
        table,
        "docs/cli.md is out of date: run PENUMBRA_WRITE_DOCS=1 cargo test --release --test cli_docs"
    );
    for option in penumbra::povray_args::table::OPTIONS {
        if let Some(key) = option.ini {
            assert!(
                text.contains(&format!("`{key}`")),
                "{key} is not in docs/cli.md"
            );
        }
    }
}
