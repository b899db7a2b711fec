//! How much room a line of text takes: a conservative estimate for the fonts `sans-serif`
//! resolves to, from which every text of the drawings is laid out (and the drawing tests
//! check the layout).
//!
//! The estimate bounds the advance widths, ascent and descent of DejaVu Sans, the widest of
//! the common sans-serif faces (Liberation Sans, Arial, Helvetica and Noto Sans set the same
//! text narrower): each character gets the advance of the widest glyph of its class, and
//! bold text [`BOLD`] times that. Text set in any of these fonts therefore fits the room
//! the layout reserves, whatever the viewer has installed.

use kurbo::Rect;

/// The font family of every text in the drawings.
pub(crate) const FAMILY: &str = "sans-serif";
/// Height of a line's box above the baseline, in ems (DejaVu Sans: 0.928).
pub(crate) const ASCENT: f64 = 0.95;
/// Depth of a line's box below the baseline, in ems (DejaVu Sans: 0.236).
pub(crate) const DESCENT: f64 = 0.25;
/// Bold text is at most this many times as wide as the estimate for regular text (DejaVu
/// Sans Bold against the class bounds of [`advance`]: at most 1.2, for 'r' and '!').
pub(crate) const BOLD: f64 = 1.2;

/// An upper bound of the advance width of `c` in DejaVu Sans Book, in ems; 1 em for any
/// character not listed (wider glyphs than that are not used in the drawings).
pub(crate) fn advance(c: char) -> f64 {
    match c {
        // Narrow glyphs, 0.28 to 0.41 em, and the no-break space (0.318 em).
        ' ' | '!' | '\'' | '(' | ')' | ',' | '-' | '.' | '/' | ':' | ';' | '[' | '\\' | ']'
        | '|' | '·' | '\u{a0}' | 'I' | 'J' | 'f' | 'i' | 'j' | 'l' | 'r' | 't' => 0.42,
        // The widest: 'm' 0.974 em, 'W' 0.989 em, '@' 1 em.
        'M' | 'W' | 'm' | 'w' | '%' | '@' | '…' | '—' | '\u{2003}' | '●' | '▬' => 1.0,
        // Mathematical signs, 0.838 em, and ω (0.837 em).
        '#' | '+' | '<' | '=' | '>' | '^' | '~' | '−' | '×' | '≤' | '≥' | '→' | 'ω' => {
            0.84
        }
        // Capitals up to 0.787 em (O, Q), the ampersand (0.78 em).
        'A'..='Z' | '&' => 0.8,
        'Α'..='Ω' => 0.84,
        // Greek small letters up to 0.659 em (α).
        'α'..='ω' => 0.7,
        // Digits (0.636 em), other small letters and punctuation.
        c if c.is_ascii() => 0.64,
        'é' | '°' | '–' => 0.64,
        _ => 1.0,
    }
}

/// The estimated width of `text` set in `size` px, bold or not, pixels.
pub(crate) fn width(text: &str, size: f64, bold: bool) -> f64 {
    let ems: f64 = text.chars().map(advance).sum();
    let scale = if bold { BOLD } else { 1.0 };
    ems * size * scale
}

/// Where a horizontal text's width goes from its anchor point (SVG `text-anchor`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Anchor {
    /// The text starts at the anchor point.
    Start,
    /// The text is centred on it.
    Middle,
    /// The text ends at it.
    End,
}

impl Anchor {
    /// The value of the `text-anchor` attribute.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        }
    }
}

/// The estimated box of the horizontal text `text` in `size` px with its baseline through
/// (`x`, `y`) and anchored there by `anchor`: from the ascent above the baseline to the
/// descent below, pixels (y down).
pub(crate) fn text_box(
    text: &str,
    size: f64,
    bold: bool,
    (x, y): (f64, f64),
    anchor: Anchor,
) -> Rect {
    let w = width(text, size, bold);
    let x0 = match anchor {
        Anchor::Start => x,
        Anchor::Middle => x - 0.5 * w,
        Anchor::End => x - w,
    };
    Rect::new(x0, y - ASCENT * size, x0 + w, y + DESCENT * size)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Advance widths of DejaVu Sans 2.37 Book and Bold, thousandths of an em, measured with
    /// usvg: character ("sp" for the space), Book, Bold.
    const DEJAVU_SANS: &str = r#"
    sp 318 348  ! 401 456  " 460 521  # 838 838  $ 636 696  % 950 1002  & 780 872  ' 275 306
    ( 390 457  ) 390 457  * 500 523  + 838 838  , 318 380  - 361 415  . 300 380  / 337 365
    0 636 696  1 636 696  2 636 696  3 636 696  4 636 696  5 636 696  6 636 696  7 636 696
    8 636 696  9 636 696  : 337 400  ; 337 400  < 838 838  = 838 838  > 838 838  ? 531 580
    @ 1000 1000  A 684 774  B 686 762  C 698 734  D 770 830  E 632 683  F 575 683  G 775 821
    H 752 837  I 295 372  J 295 372  K 656 775  L 557 637  M 863 995  N 748 837  O 787 850
    P 603 733  Q 787 850  R 695 770  S 635 720  T 611 682  U 732 812  V 684 774  W 989 1103
    X 685 771  Y 611 724  Z 685 725  [ 390 457  \ 337 365  ] 390 457  ^ 838 838  _ 500 500
    ` 500 500  a 613 675  b 635 716  c 550 593  d 635 716  e 615 678  f 352 435  g 635 716
    h 634 712  i 278 343  j 278 343  k 579 665  l 278 343  m 974 1042  n 634 712  o 612 687
    p 635 716  q 635 716  r 411 493  s 521 595  t 392 478  u 634 712  v 592 652  w 818 924
    x 592 645  y 592 652  z 525 582  { 636 712  | 337 365  } 636 712  ~ 838 838  α 659 687
    β 638 716  κ 589 710  λ 592 633  Λ 684 774  ν 559 681  ρ 635 716  τ 602 638  θ 612 687
    Ω 764 850  ω 837 869  − 838 838  ° 500 500  é 615 678  × 838 838  ≤ 838 838  ≥ 838 838
    · 318 380  … 1000 1000  – 500 500  — 1000 1000  → 838 838  ● 873 873  ▬ 945 945
"#;

    #[test]
    fn the_estimate_bounds_every_dejavu_sans_advance_regular_and_bold() {
        let fields: Vec<&str> = DEJAVU_SANS.split_whitespace().collect();
        let mut checked = 0;
        for row in fields.chunks(3) {
            let c = match row[0] {
                "sp" => ' ',
                c => c.chars().next().unwrap(),
            };
            let [book, bold] = [row[1], row[2]].map(|v| v.parse::<f64>().unwrap() / 1000.0);
            assert!(advance(c) >= book, "{c:?}: {} < {book}", advance(c));
            let estimate = BOLD * advance(c);
            assert!(estimate >= bold, "{c:?} bold: {estimate} < {bold}");
            checked += 1;
        }
        assert_eq!(checked, 119, "every row of the table was read");
        const { assert!(ASCENT >= 0.928 && DESCENT >= 0.236) };
    }

    #[test]
    fn a_text_box_spans_its_width_from_the_anchor_and_the_line_height_around_the_baseline() {
        let w = width("P0", 12.0, false);
        assert!((w - 12.0 * (0.8 + 0.64)).abs() < 1e-12);
        let start = text_box("P0", 12.0, false, (10.0, 50.0), Anchor::Start);
        assert_eq!((start.x0, start.x1), (10.0, 10.0 + w));
        assert!((start.y0 - (50.0 - 0.95 * 12.0)).abs() < 1e-12 && (start.y1 - 53.0).abs() < 1e-12);
        let end = text_box("P0", 12.0, false, (10.0, 50.0), Anchor::End);
        assert_eq!(end.x1, 10.0);
        let middle = text_box("P0", 12.0, true, (10.0, 50.0), Anchor::Middle);
        assert!(
            (middle.width() - BOLD * w).abs() < 1e-12 && (middle.center().x - 10.0).abs() < 1e-12
        );
    }
}
