//! The socketcand protocol, server side: the commands a client sends, the lines the
//! server answers with, and the framing of a TCP byte stream into `< ... >`
//! elements. Written from socketcand's public protocol description
//! (`doc/protocol.md` of linux-can/socketcand) and from what python-can's
//! `socketcand` interface sends and expects.
//!
//! Served: `open`, `rawmode`, `bcmmode`, `echo`, `send`, `sendrtr` and this
//! project's extension `fault` (docs/serve.md). The other socketcand commands
//! (BCM jobs and filters, control and ISO-TP modes) are answered with an error
//! that names them.
//!
//! Identifiers: exactly 8 hex digits make an extended (29-bit) identifier, 1 to 3 a
//! base one, as socketcand reads them (`element_length == 8`) and python-can
//! writes them (`%08X` / `%03X`).

use drcc_cosim::Frame;

/// The longest element accepted, `<` to `>` (socketcand's longest classical line,
/// `< send XXXXXXXX 8 xx xx xx xx xx xx xx xx >`, is 44 characters; a fault
/// command is shorter): a longer one is an error and is discarded.
pub const MAX_ELEMENT: usize = 128;

/// The longest bus name socketcand accepts in `open`.
pub const MAX_BUS_NAME: usize = 16;

/// A client's command.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    /// `< open BUS >`.
    Open(String),
    /// `< rawmode >`: every frame the bus delivers is streamed to the client.
    RawMode,
    /// `< bcmmode >`: back to BCM mode (no streaming).
    BcmMode,
    /// `< echo >`.
    Echo,
    /// `< send ID DLC DATA* >` or `< sendrtr ID DLC >`.
    Send(Frame),
    /// `< fault ARGS* >` (this project's extension; the arguments unparsed).
    Fault(Vec<String>),
}

/// socketcand commands that exist but are not served here.
const NOT_SERVED: [&str; 12] = [
    "add",
    "update",
    "delete",
    "filter",
    "muxfilter",
    "subscribe",
    "unsubscribe",
    "controlmode",
    "statistics",
    "isotpmode",
    "isotpconf",
    "sendpdu",
];

/// Parses one element (`< ... >`, as split by [`Framer`]).
pub fn parse(element: &str) -> Result<Command, String> {
    let inner = element
        .strip_prefix('<')
        .and_then(|s| s.strip_suffix('>'))
        .ok_or_else(|| {
            format!(
                "`{}` is not an element in angle brackets",
                printable(element)
            )
        })?;
    let words: Vec<&str> = inner.split_ascii_whitespace().collect();
    let Some((&verb, args)) = words.split_first() else {
        return Err("an empty element: send a command such as `open node0`".into());
    };
    let no_args = |c: Command| {
        if args.is_empty() {
            Ok(c)
        } else {
            Err(format!("`{verb}` takes no arguments"))
        }
    };
    match verb {
        "open" => match args {
            [bus] if bus.len() <= MAX_BUS_NAME => Ok(Command::Open(bus.to_string())),
            [bus] => Err(format!(
                "bus name `{}`: at most {MAX_BUS_NAME} characters",
                printable(bus)
            )),
            _ => Err("open takes one bus name: `open node0`".into()),
        },
        "rawmode" => no_args(Command::RawMode),
        "bcmmode" => no_args(Command::BcmMode),
        "echo" => no_args(Command::Echo),
        "send" => parse_send(args, false),
        "sendrtr" => parse_send(args, true),
        "fault" => Ok(Command::Fault(args.iter().map(|s| s.to_string()).collect())),
        v if NOT_SERVED.contains(&v) => Err(format!(
            "`{v}` is a socketcand command this server does not serve: use `rawmode` \
             and filter on the client"
        )),
        v => Err(format!(
            "unknown command `{}`: the commands are open, rawmode, bcmmode, echo, send, \
             sendrtr and fault",
            printable(v)
        )),
    }
}

/// The identifier of `send`: 8 hex digits extended, 1..=3 base.
fn parse_id(text: &str) -> Result<(u32, bool), String> {
    let bad = || {
        format!(
            "identifier `{}`: give 3 hex digits for a base frame (000..7FF) or 8 for an \
             extended one (00000000..1FFFFFFF)",
            printable(text)
        )
    };
    if !text.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(bad());
    }
    let id = u32::from_str_radix(text, 16).map_err(|_| bad())?;
    match text.len() {
        1..=3 if id <= 0x7FF => Ok((id, false)),
        8 if id <= 0x1FFF_FFFF => Ok((id, true)),
        _ => Err(bad()),
    }
}

/// `send ID DLC DATA*` / `sendrtr ID DLC`.
fn parse_send(args: &[&str], rtr: bool) -> Result<Command, String> {
    let usage = if rtr {
        "`sendrtr ID DLC`"
    } else {
        "`send ID DLC DATA*`"
    };
    let [id, dlc, data @ ..] = args else {
        return Err(format!("give {usage}"));
    };
    let (id, ide) = parse_id(id)?;
    let dlc: u8 = match dlc.parse() {
        Ok(d) if d <= 8 => d,
        _ => {
            return Err(format!(
                "oversized frame: DLC `{}` (a classical CAN frame carries 0..8 data bytes)",
                printable(dlc)
            ))
        }
    };
    if rtr && !data.is_empty() {
        return Err("a remote frame carries no data: `sendrtr ID DLC`".into());
    }
    if !rtr && data.len() != dlc as usize {
        return Err(format!(
            "DLC {dlc} but {} data bytes: give exactly DLC bytes{}",
            data.len(),
            if data.len() > 8 {
                " (oversized frame: at most 8)"
            } else {
                ""
            }
        ));
    }
    let mut bytes = [0u8; 8];
    for (b, text) in bytes.iter_mut().zip(data) {
        *b = match u8::from_str_radix(text, 16) {
            Ok(v) if text.len() <= 2 => v,
            _ => {
                return Err(format!(
                    "data byte `{}`: give 1 or 2 hex digits",
                    printable(text)
                ))
            }
        };
    }
    Ok(Command::Send(Frame {
        id,
        ide,
        rtr,
        dlc,
        data: bytes,
    }))
}

/// `text` with control and non-ASCII characters escaped, cut to 40 characters, for
/// error messages that quote the client.
pub fn printable(text: &str) -> String {
    let mut s: String = text
        .chars()
        .take(40)
        .flat_map(char::escape_default)
        .collect();
    if text.chars().count() > 40 {
        s.push_str("...");
    }
    s
}

/// Simulated time as socketcand prints it, `SECONDS.MICROSECONDS`.
pub fn timestamp(time_ns: u64) -> String {
    format!(
        "{}.{:06}",
        time_ns / 1_000_000_000,
        time_ns % 1_000_000_000 / 1000
    )
}

/// The identifier as socketcand prints it: `%08X` extended, `%03X` base.
fn id_text(f: &Frame) -> String {
    if f.ide {
        format!("{:08X}", f.id & 0x1FFF_FFFF)
    } else {
        format!("{:03X}", f.id & 0x7FF)
    }
}

/// A received frame: `< frame ID TIME DATA >` (data bytes `%02X` without spaces, as
/// socketcand sends them) or `< rtr ID TIME DLC >` for a remote frame.
pub fn frame_line(f: &Frame, time_ns: u64) -> String {
    let t = timestamp(time_ns);
    if f.rtr {
        return format!("< rtr {} {t} {} >", id_text(f), f.dlc.min(8));
    }
    let data: String = f.data[..f.data_len()]
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect();
    format!("< frame {} {t} {data} >", id_text(f))
}

/// An error frame: `< error CLASS TIME >` with the SocketCAN error class
/// (`can_id & CAN_EFF_MASK`), as socketcand sends it.
pub fn error_line(class: u32, time_ns: u64) -> String {
    format!(
        "< error {:03X} {} >",
        class & 0x1FFF_FFFF,
        timestamp(time_ns)
    )
}

/// The answer to a refused command. The message never contains `>` (which would
/// end the element early).
pub fn refusal(message: &str) -> String {
    format!("< error {} >", message.replace(['<', '>'], "'"))
}

/// Splits a client's byte stream into elements. Bytes outside elements must be
/// whitespace; an element longer than [`MAX_ELEMENT`] or one that is not ASCII is an
/// error, and its bytes are dropped.
#[derive(Debug, Default)]
pub struct Framer {
    buf: Vec<u8>,
    /// Inside an oversized element: drop bytes up to its `>`.
    skipping: bool,
    /// Inside a run of stray bytes outside an element (already reported).
    garbage: bool,
}

impl Framer {
    /// Takes `bytes` and returns the complete elements (or errors) in order.
    pub fn push(&mut self, bytes: &[u8]) -> Vec<Result<String, String>> {
        let mut out = Vec::new();
        for &b in bytes {
            if self.skipping {
                self.skipping = b != b'>';
                continue;
            }
            if self.buf.is_empty() {
                match b {
                    b'<' => {
                        self.garbage = false;
                        self.buf.push(b)
                    }
                    b if b.is_ascii_whitespace() => {}
                    _ if self.garbage => {}
                    b => {
                        // one error for a run of stray bytes, not one per byte
                        self.garbage = true;
                        out.push(Err(format!(
                            "text starting with `{}` outside an element: every command is \
                             written in angle brackets, e.g. `open node0` in them",
                            printable(&String::from_utf8_lossy(&[b]))
                        )))
                    }
                }
                continue;
            }
            self.buf.push(b);
            if b == b'>' {
                let e = std::mem::take(&mut self.buf);
                out.push(match String::from_utf8(e) {
                    Ok(s) if s.is_ascii() => Ok(s),
                    _ => Err("an element with non-ASCII bytes: the protocol is ASCII".into()),
                });
            } else if self.buf.len() >= MAX_ELEMENT {
                self.buf.clear();
                self.skipping = true;
                out.push(Err(format!(
                    "an element longer than {MAX_ELEMENT} characters (oversized frame or a \
                     missing `>`): it was discarded"
                )));
            }
        }
        out
    }

    /// Bytes of an unfinished element (a client that vanished mid-element).
    pub fn pending(&self) -> usize {
        self.buf.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn send(s: &str) -> Frame {
        match parse(s) {
            Ok(Command::Send(f)) => f,
            other => panic!("{s}: {other:?}"),
        }
    }

    #[test]
    fn send_reads_ids_as_socketcand_does() {
        // protocol.md's examples
        let f = send("< send 123 0 >");
        assert_eq!((f.id, f.ide, f.dlc), (0x123, false, 0));
        let f = send("< send 1AAAAAAA 2 1 F1 >");
        assert_eq!((f.id, f.ide, f.dlc), (0x1AAA_AAAA, true, 2));
        assert_eq!(&f.data[..2], &[0x01, 0xF1]);
        // what python-can writes: `%03X`, DLC in hex, bytes `%x`
        let f = send("< send 7FF 8 0 1 2 3 4 5 6 ff >");
        assert_eq!(f.data, [0, 1, 2, 3, 4, 5, 6, 0xFF]);
        let f = send("< sendrtr 1AAAAAAA 2 >");
        assert!(f.rtr && f.ide && f.dlc == 2);
    }

    #[test]
    fn bad_sends_are_refused_with_the_reason() {
        for (line, why) in [
            ("< send 800 0 >", "identifier"),
            ("< send 1234 0 >", "identifier"),
            ("< send 20000000 0 >", "identifier"),
            ("< send 12G 0 >", "identifier"),
            ("< send 123 9 0 0 0 0 0 0 0 0 0 >", "oversized"),
            ("< send 123 2 11 >", "DLC 2 but 1"),
            ("< send 123 1 100 >", "data byte"),
            ("< sendrtr 123 1 11 >", "no data"),
            ("< send 123 >", "give"),
            ("< frobnicate >", "unknown command"),
            ("< subscribe 0 0 123 >", "does not serve"),
            ("< open >", "one bus name"),
            ("< open abcdefghijklmnopq >", "at most 16"),
            ("< >", "an empty element"),
        ] {
            let e = parse(line).expect_err(line);
            assert!(e.contains(why), "{line}: {e}");
        }
    }

    #[test]
    fn lines_are_formatted_as_socketcand_sends_them() {
        let f = Frame {
            id: 0x123,
            ide: false,
            rtr: false,
            dlc: 4,
            data: [0x11, 0x22, 0x33, 0x44, 0, 0, 0, 0],
        };
        // protocol.md: "< frame 123 23.424242 11 22 33 44 >" documents spaces, while
        // socketcand's state_raw.c prints `%02X` without them, which python-can reads
        assert_eq!(
            frame_line(&f, 23_424_242_000),
            "< frame 123 23.424242 11223344 >"
        );
        let e = Frame {
            id: 0x1AAA_AAAA,
            ide: true,
            dlc: 0,
            ..f
        };
        assert_eq!(frame_line(&e, 1_000), "< frame 1AAAAAAA 0.000001  >");
        let r = Frame { rtr: true, ..f };
        assert_eq!(frame_line(&r, 0), "< rtr 123 0.000000 4 >");
        assert_eq!(error_line(0x2000_0008, 5_000_000), "< error 008 0.005000 >");
        assert_eq!(refusal("bad <x>"), "< error bad 'x' >");
    }

    #[test]
    fn the_framer_splits_elements_and_recovers_from_garbage() {
        let mut fr = Framer::default();
        let out = fr.push(b"< hi >\n< open no");
        assert_eq!(out, vec![Ok("< hi >".to_string())]);
        assert_eq!(fr.pending(), "< open no".len());
        let out = fr.push(b"de0 >xyz< echo >");
        assert_eq!(out.len(), 3);
        assert_eq!(out[0], Ok("< open node0 >".to_string()));
        assert!(out[1].is_err());
        assert_eq!(out[2], Ok("< echo >".to_string()));
        // an oversized element is one error, and the stream goes on after its `>`
        let mut long = b"< send 123 8".to_vec();
        long.extend(b" 11".repeat(100));
        long.extend(b" >< echo >".iter());
        let out = fr.push(&long);
        assert_eq!(out.len(), 2, "{out:?}");
        assert!(out[0].as_ref().unwrap_err().contains("longer than"));
        assert_eq!(out[1], Ok("< echo >".to_string()));
        let out = fr.push("< open n\u{e9} >".as_bytes());
        assert!(out[0].as_ref().unwrap_err().contains("ASCII"));
    }
}
