//! Tests of `drcc_hdl::tops::port_docs`.

use drcc_hdl::tops::port_docs::*;

mod tests {
    use super::*;

    const SOURCE: &str = "
/// Not this one.
pub struct Other {
    /// Wrong struct.
    pub a: Signal<In, Bit>,
}
pub struct Blk<const N: usize> {
    // group comment: not a doc
    /// First line,
    /// second line.
    pub a: Signal<In, Bit>,
    pub undocumented: Signal<Out, Bits<N>>,
    /// Belongs to nobody: a private field follows.
    inner: Signal<Local, Bit>,
    /// Last.
    pub z: Signal<Out, Bit>,
}
";

    #[test]
    fn docs_are_taken_from_the_named_struct_only() {
        let docs = port_docs(SOURCE, "Blk");
        assert_eq!(
            docs,
            vec![
                ("a".to_string(), "First line, second line.".to_string()),
                ("undocumented".to_string(), String::new()),
                ("z".to_string(), "Last.".to_string()),
            ]
        );
        assert!(
            port_docs(SOURCE, "Bl").is_empty(),
            "a prefix is not the name"
        );
    }

    #[test]
    fn wrap_keeps_lines_within_the_width() {
        let lines = wrap("aaa bbb ccc dddddddddd e", 7);
        assert_eq!(lines, vec!["aaa bbb", "ccc", "dddddddddd", "e"]);
        assert_eq!(wrap("", 10), vec![String::new()]);
        assert_eq!(
            wrap("see `rst = 1` now", 9),
            vec!["see", "`rst = 1`", "now"]
        );
    }
}
