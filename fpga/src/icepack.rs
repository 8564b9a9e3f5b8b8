//! icepack: packs the routed iCE40 design (`<module>.asc`) into the bitstream
//! (`<module>.bin`) that programs the board.

use std::path::{Path, PathBuf};

use crate::tools::{run_logged, ICEPACK};
use crate::Error;

/// The icepack log file, in the build directory.
pub const LOG: &str = "icepack.log";

/// Packs `<module>.asc` in `dir`; returns the bitstream's path.
pub fn run(dir: &Path, module: &str) -> Result<PathBuf, Error> {
    run_logged(
        &ICEPACK,
        &[format!("{module}.asc"), format!("{module}.bin")],
        dir,
        LOG,
    )?;
    let bitstream = dir.join(format!("{module}.bin"));
    if !bitstream.is_file() {
        return Err(Error(format!(
            "icepack wrote no bitstream {}",
            bitstream.display()
        )));
    }
    Ok(bitstream)
}
