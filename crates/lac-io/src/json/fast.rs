//! The batch fast path: `lac segment --batch` reads its common exact line shape
//! ([`SegmentInput::parse_line`]) by a direct scan instead of serde_json, and writes each
//! [`SegmentReport`] ([`SegmentReport::write_json`]) with a hand-written number writer.
//!
//! Both must give exactly what serde_json gives: the same correctly rounded doubles for every
//! number read (anything the scan does not know falls back to [`parse`], so every error
//! message is serde_json's), and the same bytes for every report written (the shortest
//! round-trip digits serde_json itself uses, from `zmij`). The tests below check both
//! against serde_json.

use super::{parse, ErrorBody, SegmentInput, SegmentReport};

impl SegmentReport {
    /// The report as one line of JSON appended to `out`, without a newline: the bytes
    /// serde_json writes (see [`to_line`](super::to_line)), formatted directly, for `--batch`.
    pub fn write_json(&self, out: &mut Vec<u8>) {
        let mut w = NumberWriter::default();
        out.extend_from_slice(b"{\"alpha\":");
        w.num(out, self.alpha);
        out.extend_from_slice(b",\"lambda\":");
        w.num(out, self.lambda);
        out.extend_from_slice(b",\"arc_length\":");
        let length = w.num(out, self.arc_length);
        out.extend_from_slice(b",\"curvature_start\":");
        let kappa_start = w.num(out, self.curvature_start);
        out.extend_from_slice(b",\"curvature_end\":");
        let kappa_end = w.num(out, self.curvature_end);
        out.extend_from_slice(b",\"turning_angle\":");
        w.num(out, self.turning_angle);
        out.extend_from_slice(b",\"points\":[");
        let points = self.points.each_ref().map(|&[x, y]| {
            out.extend_from_slice(if out.ends_with(b"[") { b"[" } else { b",[" });
            let x = w.num(out, x);
            out.push(b',');
            let y = w.num(out, y);
            out.push(b']');
            [x, y]
        });
        out.extend_from_slice(b"],\"samples\":[");
        // The end samples repeat the arc length, the end curvatures and (usually) the end
        // points: their bytes are copied rather than formatted again.
        let last = self.samples.len().saturating_sub(1);
        for (i, row) in self.samples.iter().enumerate() {
            let ends = if i == 0 {
                Some((&points[0], &kappa_start, None))
            } else if i == last {
                Some((&points[2], &kappa_end, Some(&length)))
            } else {
                None
            };
            out.extend_from_slice(if i == 0 { b"{\"s\":" } else { b",{\"s\":" });
            w.again(out, row.s, ends.and_then(|e| e.2));
            out.extend_from_slice(b",\"x\":");
            w.again(out, row.x, ends.map(|e| &e.0[0]));
            out.extend_from_slice(b",\"y\":");
            w.again(out, row.y, ends.map(|e| &e.0[1]));
            out.extend_from_slice(b",\"theta\":");
            w.num(out, row.theta);
            out.extend_from_slice(b",\"kappa\":");
            w.again(out, row.kappa, ends.map(|e| e.1));
            out.push(b'}');
        }
        out.extend_from_slice(b"]}");
    }
}

/// Writes numbers as serde_json does, and copies one already written when it is the same.
#[derive(Default)]
struct NumberWriter {
    floats: zmij::Buffer,
}

/// A number [`NumberWriter`] has written, and where.
struct Written {
    x: f64,
    bytes: std::ops::Range<usize>,
}

impl NumberWriter {
    /// `x` appended to `out` (`null` when not finite).
    fn num(&mut self, out: &mut Vec<u8>, x: f64) -> Written {
        let start = out.len();
        if x.is_finite() {
            push_short(out, self.floats.format_finite(x).as_bytes());
        } else {
            out.extend_from_slice(b"null");
        }
        Written {
            x,
            bytes: start..out.len(),
        }
    }

    /// `x` appended to `out`, copied from `before` when that is the same number.
    fn again(&mut self, out: &mut Vec<u8>, x: f64, before: Option<&Written>) {
        match before {
            Some(b) if b.x.to_bits() == x.to_bits() => {
                let mut copy = [0; SHORT];
                let n = short_copy(&mut copy, &out[b.bytes.clone()]);
                push_short(out, &copy[..n]);
            }
            _ => {
                self.num(out, x);
            }
        }
    }
}

/// The longest [`push_short`] copies: a number as zmij writes it has at most 24 bytes.
const SHORT: usize = 32;

/// `bytes` appended to `out`, as [`short_copy`] copies them.
fn push_short(out: &mut Vec<u8>, bytes: &[u8]) {
    let at = out.len();
    out.extend_from_slice(&[0; SHORT]);
    let n = short_copy(&mut out[at..], bytes);
    out.truncate(at + n);
}

/// The first `SHORT` bytes or fewer of `bytes` copied to the start of `dst` (which has
/// room for `SHORT`), returning how many: by two overlapping copies of a fixed size, which
/// compile to a few moves (a call of memcpy for each of some twenty short numbers a line
/// costs more than writing them).
fn short_copy(dst: &mut [u8], bytes: &[u8]) -> usize {
    let n = bytes.len().min(SHORT).min(dst.len());
    let (dst, bytes) = (&mut dst[..n], &bytes[..n]);
    fn two<const K: usize>(dst: &mut [u8], bytes: &[u8]) {
        if let (Some(d), Some(b)) = (dst.first_chunk_mut::<K>(), bytes.first_chunk::<K>()) {
            *d = *b;
        }
        if let (Some(d), Some(b)) = (dst.last_chunk_mut::<K>(), bytes.last_chunk::<K>()) {
            *d = *b;
        }
    }
    match n {
        16.. => two::<16>(dst, bytes),
        8.. => two::<8>(dst, bytes),
        4.. => two::<4>(dst, bytes),
        _ => dst.iter_mut().zip(bytes).for_each(|(d, b)| *d = *b),
    }
    n
}

impl SegmentInput {
    /// Read a `--batch` line: the common exact shape
    /// `{"points":[[x,y],[x,y],[x,y]],"alpha":A}` (any JSON whitespace, fields in this order)
    /// by a direct scan, anything else (other orders, escapes, errors) by [`parse`], so the
    /// numbers are the same correctly rounded doubles and every message is serde_json's.
    pub fn parse_line(text: &str) -> Result<SegmentInput, ErrorBody> {
        match scan_segment_input(text) {
            Some(input) => Ok(input),
            None => parse(text, Self::SHAPE),
        }
    }
}

/// The direct scan of [`SegmentInput::parse_line`]; `None` for anything it does not know.
fn scan_segment_input(text: &str) -> Option<SegmentInput> {
    let mut at = Scan {
        text: text.as_bytes(),
        source: text,
        pos: 0,
    };
    at.expect(b'{')?;
    at.key(b"points")?;
    at.expect(b'[')?;
    let mut points = [[0.0; 2]; 3];
    for (i, p) in points.iter_mut().enumerate() {
        if i > 0 {
            at.expect(b',')?;
        }
        at.expect(b'[')?;
        p[0] = at.number()?;
        at.expect(b',')?;
        p[1] = at.number()?;
        at.expect(b']')?;
    }
    at.expect(b']')?;
    at.expect(b',')?;
    at.key(b"alpha")?;
    let alpha = at.number()?;
    at.expect(b'}')?;
    at.skip_space();
    (at.pos == text.len()).then_some(SegmentInput { points, alpha })
}

struct Scan<'a> {
    text: &'a [u8],
    /// The same text as a `str`, to slice numbers from (they are ASCII).
    source: &'a str,
    pos: usize,
}

impl Scan<'_> {
    fn skip_space(&mut self) {
        while let Some(b' ' | b'\t' | b'\n' | b'\r') = self.text.get(self.pos) {
            self.pos += 1;
        }
    }

    fn expect(&mut self, byte: u8) -> Option<()> {
        self.skip_space();
        (self.text.get(self.pos) == Some(&byte)).then(|| self.pos += 1)
    }

    /// `"name":` (no escapes).
    fn key(&mut self, name: &[u8]) -> Option<()> {
        self.expect(b'"')?;
        let end = self.pos + name.len();
        (self.text.get(self.pos..end) == Some(name)).then_some(())?;
        self.pos = end;
        (self.text.get(self.pos) == Some(&b'"')).then_some(())?;
        self.pos += 1;
        self.expect(b':')
    }

    /// A number in JSON's grammar, `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`, read
    /// correctly rounded (as serde_json's float_roundtrip does); `None` for anything else,
    /// and for magnitudes that overflow (serde_json's error is the one to give).
    fn number(&mut self) -> Option<f64> {
        self.skip_space();
        let start = self.pos;
        let negative = self.text.get(self.pos) == Some(&b'-');
        if negative {
            self.pos += 1;
        }
        // The first 19 significant digits in `digits`, the value being digits × 10^exponent
        // plus what was dropped, if any digit was (only once `digits` ≥ 10^18).
        let (mut digits, mut exponent, mut dropped) = (0u64, 0i64, false);
        let mut read = |s: &mut Self, fraction: bool| {
            let from = s.pos;
            // Eight digits at a time while they fit (shortest round-trip output has 15–17).
            while digits < 10_000_000_000 {
                let Some(eight) = s.text.get(s.pos..s.pos + 8).and_then(eight_digits) else {
                    break;
                };
                digits = 100_000_000 * digits + eight;
                exponent -= 8 * i64::from(fraction);
                s.pos += 8;
            }
            while let Some(&b) = s.text.get(s.pos) {
                if !b.is_ascii_digit() {
                    break;
                }
                if digits < 1_000_000_000_000_000_000 {
                    digits = 10 * digits + u64::from(b - b'0');
                    exponent -= i64::from(fraction);
                } else {
                    exponent += i64::from(!fraction);
                    dropped = true;
                }
                s.pos += 1;
            }
            s.pos - from
        };
        let first = *self.text.get(self.pos)?;
        let int = read(self, false);
        if int == 0 || (first == b'0' && int > 1) {
            return None;
        }
        if self.text.get(self.pos) == Some(&b'.') {
            self.pos += 1;
            if read(self, true) == 0 {
                return None;
            }
        }
        if let Some(b'e' | b'E') = self.text.get(self.pos) {
            self.pos += 1;
            let sign = match self.text.get(self.pos) {
                Some(b'-') => -1,
                Some(b'+') => 1,
                _ => 0,
            };
            self.pos += usize::from(sign != 0);
            let from = self.pos;
            let mut power = 0i64;
            while let Some(&b) = self.text.get(self.pos).filter(|b| b.is_ascii_digit()) {
                power = (10 * power + i64::from(b - b'0')).min(1 << 40);
                self.pos += 1;
            }
            if self.pos == from {
                return None;
            }
            exponent += if sign < 0 { -power } else { power };
        }
        // Clinger's fast path: both factors exact doubles, so one correctly rounded
        // operation gives the correctly rounded value; the rest by the standard library.
        let magnitude = if digits == 0 {
            0.0
        } else if digits <= 1 << 53 && exponent.abs() <= 22 {
            let power = POWERS_OF_TEN[exponent.unsigned_abs() as usize];
            if exponent >= 0 {
                digits as f64 * power
            } else {
                digits as f64 / power
            }
        } else if let Some(x) = exactly_rounded(digits, exponent).filter(|_| !dropped) {
            x
        } else {
            let token = self.source.get(start..self.pos)?;
            return token.parse::<f64>().ok().filter(|x| x.is_finite());
        };
        Some(if negative { -magnitude } else { magnitude })
    }
}

/// digits × 10^exponent correctly rounded, by exact integer arithmetic in 128 bits, for
/// the 17- to 19-digit numbers that shortest round-trip output writes (beyond Clinger's
/// fast path) with |exponent| ≤ 19; `None` for the rest.
fn exactly_rounded(digits: u64, exponent: i64) -> Option<f64> {
    let power = 10u128.checked_pow(u32::try_from(exponent.unsigned_abs()).ok()?)?;
    if !(1..=19).contains(&exponent.abs()) {
        return None;
    }
    if exponent > 0 {
        // An exact integer below 2^128; `as` rounds it to nearest, ties to even.
        return Some((u128::from(digits) * power) as f64);
    }
    // digits / 10^k: shift digits to the top of 128 bits, divide, and fold a non-zero
    // remainder into the lowest bit (a sticky bit: the quotient has at least 128 − 64 = 64
    // bits, so that bit lies far below the rounding position) before rounding to a double.
    let shift = digits.leading_zeros() + 64;
    let numerator = u128::from(digits) << shift;
    let (quotient, remainder) = (numerator / power, numerator % power);
    let rounded = (quotient | u128::from(remainder != 0)) as f64;
    // × 2^−shift, exact: the result is at least 10^−19, a normal number.
    Some(rounded * f64::from_bits((1023 - u64::from(shift)) << 52))
}

/// The value of eight ASCII digits, `None` unless all eight are digits: all at once, in the
/// bytes of one `u64` (the first digit in the lowest byte).
fn eight_digits(bytes: &[u8]) -> Option<u64> {
    let v = u64::from_le_bytes(bytes.try_into().ok()?);
    // Every byte 0x30–0x39: high nibble 3, and adding 6 does not carry out of the low one.
    let high = 0xF0F0_F0F0_F0F0_F0F0;
    let threes = 0x3030_3030_3030_3030;
    if v & high != threes || v.wrapping_add(0x0606_0606_0606_0606) & high != threes {
        return None;
    }
    let d = v - threes;
    // Pairs: byte 2i holds 10·d(2i) + d(2i+1).
    let pairs = d.wrapping_mul(10).wrapping_add(d >> 8);
    // Bytes 0 and 4 (pairs 1 and 3), bytes 2 and 6 (pairs 2 and 4), weighted and summed
    // in the high half.
    let mask = 0x0000_00FF_0000_00FF;
    let odd = (pairs & mask).wrapping_mul(100 + (1_000_000 << 32));
    let even = ((pairs >> 16) & mask).wrapping_mul(1 + (10_000 << 32));
    Some(odd.wrapping_add(even) >> 32)
}

/// 10^0 … 10^22, every one exact in a double.
const POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

#[cfg(test)]
mod tests {
    use super::*;
    use kurbo::Point;
    use lac::Segment;

    /// The scan's number against the standard library's reading of the same token, and
    /// JSON's grammar: on edge cases of the fast paths (2^53, 10^22, 19 digits, zeros, near
    /// ties) and on 200,000 random tokens of every length and exponent.
    #[test]
    fn numbers_are_read_correctly_rounded_and_only_in_json_grammar() {
        let read = |token: &str| {
            let mut scan = Scan {
                text: token.as_bytes(),
                source: token,
                pos: 0,
            };
            scan.number().filter(|_| scan.pos == token.len())
        };
        let check = |token: &str| {
            let want = token.parse::<f64>().ok().filter(|x| x.is_finite());
            let got = read(token);
            assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "{token}");
        };
        for token in [
            "0",
            "-0",
            "0.0",
            "-0.0e5",
            "0e-400",
            "1",
            "-1.0",
            "9007199254740992",
            "9007199254740993",
            "9007199254740994",
            "9007199254740995",
            "1e22",
            "1e23",
            "9007199254740993e22",
            "4.9e-324",
            "2.2250738585072011e-308",
            "1.7976931348623157e308",
            "1e-22",
            "123456789012345678901234567890",
            "1234567890123456789e-19",
            "12345678901234567890",
            "0.10000000000000000555",
            "0.1000000000000000055511151231257827",
            "416.4634885398515",
            "-47.60845231828477",
            "0.0037720556121437544",
            "1E+2",
            "1e-2",
            // Just above a tie in the 128-bit division: only its remainder rounds them up.
            "5.51591418255067234",
            "5.524963189587341450",
            "3.204061910968816429",
            "6.611647786041852104",
        ] {
            check(token);
        }
        for (text, value) in [
            ("00000000", 0),
            ("12345678", 12_345_678),
            ("99999999", 99_999_999),
        ] {
            assert_eq!(eight_digits(text.as_bytes()), Some(value));
        }
        for text in ["1234567a", "/2345678", ":2345678", "1234 678", "1234567"] {
            assert_eq!(eight_digits(text.as_bytes()), None, "{text}");
        }
        for bad in [
            "", "-", "+1", "01", "-01", ".5", "1.", "1e", "1e+", "inf", "NaN", "1e400", "-2e308",
        ] {
            assert_eq!(read(bad), None, "{bad}");
        }
        // xorshift64*: tokens of 1–25 digits, a point anywhere, exponents to ±330.
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            state.wrapping_mul(0x2545_F491_4F6C_DD1D)
        };
        for _ in 0..200_000 {
            let count = 1 + (next() % 25) as usize;
            let mut digits: String = (0..count)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            if digits.len() > 1 && digits.starts_with('0') {
                digits.replace_range(0..1, "1");
            }
            let mut token = if next() % 2 == 0 {
                "-".to_string()
            } else {
                String::new()
            };
            let point = (next() % (count as u64 + 1)) as usize;
            if point > 0 && point < count {
                token.push_str(&digits[..point]);
                token.push('.');
                token.push_str(&digits[point..]);
            } else {
                token.push_str(&digits);
            }
            match next() % 3 {
                0 => {}
                1 => token.push_str(&format!("e{}", (next() % 45) as i64 - 22)),
                _ => token.push_str(&format!("e{}", (next() % 661) as i64 - 330)),
            }
            check(&token);
        }
    }

    #[test]
    fn segment_reports_are_written_byte_for_byte_as_serde_json_writes_them() {
        let seg = Segment::from_control_points(
            [
                Point::new(0.0, 0.0),
                Point::new(3.0, 0.0),
                Point::new(4.0, 1.5),
            ],
            -1.0,
        )
        .unwrap();
        let mut report = SegmentReport::new(&seg, 5).unwrap();
        for extra in [0.0, -0.0, 1e-300, 123456789.0, f64::NAN, f64::INFINITY] {
            report.samples[1].theta = extra;
            report.lambda = -extra;
            let mut out = b"prefix".to_vec();
            report.write_json(&mut out);
            assert_eq!(
                std::str::from_utf8(&out[6..]).unwrap(),
                serde_json::to_string(&report).unwrap()
            );
        }
        report.samples.clear();
        let mut out = Vec::new();
        report.write_json(&mut out);
        assert_eq!(out, serde_json::to_vec(&report).unwrap());
    }

    #[test]
    fn segment_lines_read_by_the_scan_are_what_serde_json_reads() {
        let lines = [
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":-1}"#,
            r#" { "points" : [ [ -1.5e-3 , 0.0 ] , [0.2, 8E+2], [1e400, -0] ] , "alpha": 0.5 }  "#,
            r#"{"points": [[-1.0, 0.0], [0.30000000000000004, 0.1], [1, 0]], "alpha": -0}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":12345678901234567890123}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":2.4703282292062328e-324}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":-1,"extra":1}"#,
            r#"{"alpha":-1,"points":[[-1,0],[0.2,0.8],[1,0]]}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":01}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":1.}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":.5}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":+1}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":NaN}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":inf}"#,
            r#"{"points":[[-1,0],[0.2,0.8]],"alpha":1}"#,
            r#"{"points":[[-1,0],[0.2,0.8],[1,0]],"alpha":1}x"#,
            r#"{"po\u0069nts":[[-1,0],[0.2,0.8],[1,0]],"alpha":1}"#,
            "",
            "  ",
        ];
        for line in lines {
            let scanned = SegmentInput::parse_line(line);
            let serde = parse::<SegmentInput>(line, SegmentInput::SHAPE);
            match (scanned, serde) {
                (Ok(a), Ok(b)) => {
                    let bits = |i: &SegmentInput| {
                        (i.points.map(|p| p.map(f64::to_bits)), i.alpha.to_bits())
                    };
                    assert_eq!(bits(&a), bits(&b), "{line}");
                }
                (Err(a), Err(b)) => assert_eq!(a, b, "{line}"),
                (a, b) => panic!("{line}: {a:?} against {b:?}"),
            }
        }
        assert!(scan_segment_input(lines[0]).is_some());
        assert!(scan_segment_input(lines[1]).is_none(), "1e400 overflows");
        assert!(scan_segment_input(lines[2]).is_some());
    }
}
