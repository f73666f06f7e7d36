use skylux_regmap::*;

#[test]
fn map_is_valid() {
    if let Err(errors) = validate() {
        panic!("register map is inconsistent: {errors:#?}");
    }
}

#[test]
fn validation_catches_broken_maps() {
    const F1: Field = Field {
        name: "A",
        lsb: 0,
        width: 8,
        access: Access::RW,
        reset: 0x100,
        doc: "",
    };
    const F2: Field = Field {
        name: "B",
        lsb: 4,
        width: 30,
        access: Access::RW,
        reset: 0,
        doc: "",
    };
    const R1: Register = Register {
        name: "r",
        offset: 0x2002,
        count: 1,
        fields: &[F1, F2],
        doc: "",
    };
    const R2: Register = Register {
        name: "r",
        offset: 0x2000,
        count: 2,
        fields: &[F1],
        doc: "",
    };
    const B: Block = Block {
        name: "bad",
        base: 0x1000,
        registers: &[R1, R2],
        doc: "",
    };
    let errors = validate_blocks(&[B]).unwrap_err();
    let text: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
    for needle in [
        "not word aligned",
        "outside its block",
        "does not fit in 32",
        "reset value",
        "overlaps",
        "defined twice",
    ] {
        assert!(
            text.iter().any(|t| t.contains(needle)),
            "missing '{needle}' in {text:#?}"
        );
    }
}

#[test]
fn field_helpers_round_trip() {
    let f = seq::status::INDEX;
    assert_eq!(f.mask(), 0x70);
    assert_eq!(f.get(f.set(0xFFFF_FFFF, 5)), 5);
    assert_eq!(
        f.set(0, 9),
        1 << 4,
        "values are truncated to the field width"
    );
    assert!(!f.fits(8));
}

#[test]
fn locate_finds_array_elements_and_rejects_holes() {
    let loc = locate(seq::exp_gain::REG.offset + 12).unwrap();
    assert_eq!(loc.register.name, "exp_gain");
    assert_eq!(loc.index, 3);
    assert!(locate(sys::id::REG.offset + 2).is_none(), "unaligned");
    assert!(locate(0x0FFC).is_none(), "hole in the sys page");
    assert!(locate(0x1F_FFFC).is_none(), "end of the window");
}

#[test]
fn reset_image_covers_every_register_once() {
    let image = reset_image();
    let expected: u32 = MAP.iter().flat_map(|b| b.registers).map(|r| r.count).sum();
    assert_eq!(image.len() as u32, expected);
    assert!(image.windows(2).all(|w| w[0].0 < w[1].0));
    assert!(image.contains(&(sys::id::REG.offset, DESIGN_ID)));
    assert!(image.contains(&(i2c::target::REG.offset, 0x5D)));
}
