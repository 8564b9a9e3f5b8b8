//! Register-map tables and what is generated from them. A map is a constant
//! table of [`Register`]s with their [`Field`]s and the named encodings
//! ([`Encoding`]) of coded fields; the DRCC's (`super::registers`) and the
//! hub's (`super::hub_registers`) are written in this form. From a table:
//!
//! - `super::generate` writes the register document (`docs/registers.md`,
//!   `docs/hub_registers.md`) and the C header (`rtl-out/drcc_regs.h`,
//!   `rtl-out/hub_regs.h`), both through `drcc generate` (`crate::generated`);
//! - [`lsb`] gives a register block a field's position as an RTL constant and
//!   [`placed`] checks a position the RTL fixes structurally: both panic, naming
//!   the field, when the RTL's width disagrees with the table, so every test
//!   that builds the block fails on a table change the RTL does not follow.

use rust_hdl::prelude::*;

/// Host access of a register.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// Read only: a write is refused and sets `INT_STATUS.illegal`.
    Ro,
    /// Read and write.
    Rw,
    /// Read, write 1 to clear.
    W1c,
    /// Write only (a command): reads 0.
    Wo,
}

impl Access {
    /// The abbreviation used in the documentation.
    pub fn label(self) -> &'static str {
        match self {
            Access::Ro => "RO",
            Access::Rw => "RW",
            Access::W1c => "R/W1C",
            Access::Wo => "WO",
        }
    }
}

/// One named code of a coded field (a mode, a policy, a state).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Encoding {
    /// Name in the documentation and the C header (upper case).
    pub name: &'static str,
    pub value: u32,
    pub desc: &'static str,
}

/// Defines a `#[repr(u32)]` enum of named codes and its [`Encoding`] table
/// (`ENCODING`) from one list, so a code is written once.
#[macro_export]
macro_rules! register_enum {
    (
        $(#[$meta:meta])*
        pub enum $name:ident { $( $(#[doc = $doc:literal])* $var:ident = $val:literal => $label:literal ),+ $(,)? }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        #[repr(u32)]
        pub enum $name { $( $(#[doc = $doc])* $var = $val ),+ }

        impl $name {
            /// Every code, in order, for the register table and its generators.
            pub const ENCODING: &'static [$crate::host::map::Encoding] = &[
                $( $crate::host::map::Encoding { name: $label, value: $val, desc: concat!($($doc),*) } ),+
            ];

            /// The field value of this code.
            pub const fn code(self) -> u32 {
                self as u32
            }

            /// The code of a field value, if it names one.
            pub fn from_code(value: u32) -> Option<Self> {
                [$( $name::$var ),+].into_iter().find(|v| *v as u32 == value)
            }
        }
    };
}

/// One field of a register.
#[derive(Clone, Copy, Debug)]
pub struct Field {
    pub name: &'static str,
    /// Least significant bit.
    pub lsb: u32,
    /// Width in bits.
    pub width: u32,
    /// Value after `rst` (for a [`Field::held`] field: after power-up only).
    pub reset: u32,
    /// Not reset by `rst`: the field reads a memory's output (the RX FIFO's
    /// head), which keeps what it held before a warm reset. Documented as
    /// "not reset" with the flag that says when it is meaningful.
    pub held: bool,
    /// Configuration field: writable only in reset mode.
    pub cfg: bool,
    /// Command: writing 1 acts, the field reads 0.
    pub command: bool,
    pub desc: &'static str,
    /// Named codes of the field (empty for a number).
    pub codes: &'static [Encoding],
}

impl Field {
    /// The field's bits in place.
    pub const fn mask(&self) -> u32 {
        (((1u64 << self.width) - 1) << self.lsb) as u32
    }

    /// The same field, not reset by `rst` (see [`Field::held`]).
    pub const fn not_reset(self) -> Field {
        Field { held: true, ..self }
    }

    /// The same field with named codes.
    pub const fn coded(self, codes: &'static [Encoding]) -> Field {
        Field { codes, ..self }
    }

    /// `value` placed in the field (excess bits dropped).
    pub const fn put(&self, value: u32) -> u32 {
        ((value as u64) << self.lsb) as u32 & self.mask()
    }

    /// The field's value in the register word `word`.
    pub const fn get(&self, word: u32) -> u32 {
        (word & self.mask()) >> self.lsb
    }
}

/// A status or command field (no reset-mode restriction).
pub const fn f(name: &'static str, lsb: u32, width: u32, reset: u32, desc: &'static str) -> Field {
    Field {
        name,
        lsb,
        width,
        reset,
        cfg: false,
        command: false,
        held: false,
        desc,
        codes: &[],
    }
}

/// A command field: writing 1 acts, it reads 0.
pub const fn cmd(name: &'static str, lsb: u32, desc: &'static str) -> Field {
    Field {
        command: true,
        ..f(name, lsb, 1, 0, desc)
    }
}

/// A configuration field: writable only in reset mode.
pub const fn cfg(
    name: &'static str,
    lsb: u32,
    width: u32,
    reset: u32,
    desc: &'static str,
) -> Field {
    Field {
        cfg: true,
        ..f(name, lsb, width, reset, desc)
    }
}

/// `a == b` in a const context.
const fn str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The field `reg.field` of `registers`, usable in a `const` (a missing field
/// fails the build).
pub const fn find(registers: &[Register], reg: &str, field: &str) -> Field {
    let mut r = 0;
    while r < registers.len() {
        if str_eq(registers[r].name, reg) {
            let fields = registers[r].fields;
            let mut f = 0;
            while f < fields.len() {
                if str_eq(fields[f].name, field) {
                    return fields[f];
                }
                f += 1;
            }
        }
        r += 1;
    }
    panic!("no such register field")
}

/// One 32-bit register.
#[derive(Clone, Copy, Debug)]
pub struct Register {
    pub name: &'static str,
    /// Word index (`wb_adr_i`); byte offset = 4 x index.
    pub index: u32,
    pub access: Access,
    pub desc: &'static str,
    pub fields: &'static [Field],
}

impl Register {
    /// Byte offset.
    pub const fn offset(&self) -> u32 {
        self.index * 4
    }

    /// Value read right after `rst`.
    pub fn reset_value(&self) -> u32 {
        if self.access == Access::Wo {
            return 0;
        }
        self.fields.iter().fold(0, |acc, f| acc | f.put(f.reset))
    }

    /// The field named `name`.
    pub fn field(&self, name: &str) -> Option<&'static Field> {
        self.fields.iter().find(|f| f.name == name)
    }

    /// Every defined bit.
    pub fn defined(&self) -> u32 {
        self.fields.iter().fold(0, |acc, f| acc | f.mask())
    }
}

/// A named list of codes shown in the document and the header.
#[derive(Clone, Copy, Debug)]
pub struct CodeList {
    /// Prefix of the C names (`<PREFIX>_<LIST>_<CODE>`).
    pub name: &'static str,
    pub desc: &'static str,
    pub codes: &'static [Encoding],
}

/// A whole register map and the text around it.
#[derive(Clone, Copy, Debug)]
pub struct RegisterMap {
    /// Document title.
    pub title: &'static str,
    /// Prefix of every C name (`DRCC`, `HUB`).
    pub prefix: &'static str,
    /// Header file name (`drcc_regs.h`).
    pub header: &'static str,
    /// Source file of the table, named in the generated files.
    pub source: &'static str,
    /// Markdown paragraphs after the title (behaviour, conventions).
    pub intro: &'static str,
    pub registers: &'static [Register],
    /// Code lists that belong to no single field (state encodings).
    pub lists: &'static [CodeList],
    /// Extra `#define`s (name without prefix, value) for the header.
    pub defines: &'static [(&'static str, u32)],
    /// Size macros of the header, each `(name, register, field)`: the field's
    /// reset value (the default top's size) as an overridable `#ifndef` default.
    pub sizes: &'static [(&'static str, &'static str, &'static str)],
}

impl RegisterMap {
    /// The register named `name`.
    pub fn register(&self, name: &str) -> Option<&'static Register> {
        self.registers.iter().find(|r| r.name == name)
    }

    /// The field `reg.field`; panics naming it when the table has none.
    pub fn field(&self, reg: &str, field: &str) -> &'static Field {
        self.register(reg)
            .and_then(|r| r.field(field))
            .unwrap_or_else(|| panic!("register map {}: no field {reg}.{field}", self.prefix))
    }

    /// Checks the table: fields inside 32 bits, not overlapping, reset values
    /// that fit, codes that fit their field.
    pub fn check(&self) -> Result<(), String> {
        for r in self.registers {
            let mut used = 0u32;
            for fl in r.fields {
                let name = format!("{}.{}", r.name, fl.name);
                if fl.width == 0 || fl.lsb + fl.width > 32 {
                    return Err(format!("{name}: bits outside the word"));
                }
                if used & fl.mask() != 0 {
                    return Err(format!("{name}: overlaps another field"));
                }
                if fl.width < 32 && fl.reset >> fl.width != 0 {
                    return Err(format!("{name}: reset value does not fit"));
                }
                if let Some(c) = fl
                    .codes
                    .iter()
                    .find(|c| fl.width < 32 && c.value >> fl.width != 0)
                {
                    return Err(format!("{name}: code {} does not fit", c.name));
                }
                used |= fl.mask();
            }
        }
        Ok(())
    }
}

/// The position of `reg.field` as an RTL constant (a Verilog localparam, used
/// as `get_bits::<W>(c.val().index())` and `<< c.val()`). `width` is the width
/// the RTL gives the field; a table that disagrees panics, naming the field.
pub fn lsb<const B: usize>(
    map: &RegisterMap,
    reg: &str,
    field: &str,
    width: u32,
) -> Constant<Bits<B>> {
    let fl = map.field(reg, field);
    assert_eq!(
        fl.width, width,
        "register map {}: {reg}.{field} is {} bits wide in the table, {width} in the RTL",
        map.prefix, fl.width
    );
    Constant::new((fl.lsb as u64).into())
}

/// Checks a position the RTL fixes by its structure (a field that is part of a
/// wider word such as the frame layout); panics, naming the field, when the
/// table disagrees.
pub fn placed(map: &RegisterMap, reg: &str, field: &str, lsb: u32, width: u32) {
    let fl = map.field(reg, field);
    assert!(
        fl.lsb == lsb && fl.width == width,
        "register map {}: {reg}.{field} is {}+:{} in the table, {lsb}+:{width} in the RTL",
        map.prefix,
        fl.lsb,
        fl.width
    );
}
