//! Generates the rust-hdl register file from the register map, so that no offset, field or
//! reset value is written twice. The output is `$OUT_DIR/register_file.rs`, included by
//! `src/regfile.rs`.

mod register_file;

fn main() {
    println!("cargo:rerun-if-changed=build");
    if let Err(errors) = skylux_regmap::validate() {
        for e in &errors {
            println!("cargo:warning=register map: {e}");
        }
        panic!("the register map is inconsistent ({} errors)", errors.len());
    }
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("register_file.rs");
    std::fs::write(out, register_file::generate(skylux_regmap::MAP)).unwrap();
}
