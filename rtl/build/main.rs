//! Generates the rust-hdl register file and the whole core's wiring from the register map, so
//! that no offset, field or reset value is written twice. The outputs are
//! `$OUT_DIR/register_file.rs` (included by `src/regfile.rs`) and `$OUT_DIR/core.rs`
//! (included by `src/core.rs`).

mod core;
mod register_file;

fn main() {
    println!("cargo:rerun-if-changed=build");
    if let Err(errors) = skylux_regmap::validate() {
        for e in &errors {
            println!("cargo:warning=register map: {e}");
        }
        panic!("the register map is inconsistent ({} errors)", errors.len());
    }
    let out_dir = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap());
    std::fs::write(
        out_dir.join("register_file.rs"),
        register_file::generate(skylux_regmap::MAP),
    )
    .unwrap();
    std::fs::write(out_dir.join("core.rs"), core::generate(skylux_regmap::MAP)).unwrap();
}
