//! Rendering one of our SVG documents to PNG with resvg (usvg to parse, tiny-skia to
//! paint), pixel for pixel at the document's size.
//!
//! Text is drawn with the system's fonts (fontdb reads the fontconfig setup); where there
//! are none, the picture is still produced, without its text.

use std::io;
use std::sync::Arc;

use resvg::tiny_skia::{Color, Pixmap, Transform};
use resvg::usvg::{fontdb, Options, Tree};

use lac_io::json::ErrorBody;

/// The PNG of `svg`, with the system's fonts.
pub(crate) fn png(svg: &str) -> Result<Vec<u8>, ErrorBody> {
    render_png(svg, system_fonts())
}

/// Sans-serif families to stand for "sans-serif" when fontdb's default (Arial) is missing,
/// in order of preference: DejaVu Sans first, the face the drawings' text estimate bounds
/// (`svg/measure.rs`).
const SANS: [&str; 6] = [
    "DejaVu Sans",
    "Liberation Sans",
    "Noto Sans",
    "Arial",
    "Helvetica",
    "FreeSans",
];

/// The fonts installed on this machine, with "sans-serif" mapped to one that exists.
fn system_fonts() -> Arc<fontdb::Database> {
    let mut fonts = fontdb::Database::new();
    fonts.load_system_fonts();
    let sans = [fontdb::Family::SansSerif];
    let query = fontdb::Query {
        families: &sans,
        ..Default::default()
    };
    if fonts.query(&query).is_none() {
        let families: Vec<&str> = fonts
            .faces()
            .flat_map(|f| f.families.iter().map(|(name, _)| name.as_str()))
            .collect();
        if let Some(name) = sans_family(&families).map(str::to_string) {
            fonts.set_sans_serif_family(name);
        }
    }
    Arc::new(fonts)
}

/// The family among `installed` to draw "sans-serif" text in: one of [`SANS`], else the
/// first whose name says "Sans" and not "Mono", else the first (any font beats no text;
/// the first face found is often a serif or monospaced one).
fn sans_family<'a>(installed: &[&'a str]) -> Option<&'a str> {
    SANS.iter()
        .find_map(|want| installed.iter().find(|name| *name == want))
        .or_else(|| {
            installed
                .iter()
                .find(|name| name.contains("Sans") && !name.contains("Mono"))
        })
        .or(installed.first())
        .copied()
}

/// The PNG of `svg` with text in `fonts`, on white.
fn render_png(svg: &str, fonts: Arc<fontdb::Database>) -> Result<Vec<u8>, ErrorBody> {
    let failed = |what: &str, e: &dyn std::fmt::Display| {
        crate::errors::io(what, None, &io::Error::other(e.to_string()))
    };
    let options = Options {
        fontdb: fonts,
        ..Options::default()
    };
    let tree = Tree::from_str(svg, &options).map_err(|e| failed("render the picture", &e))?;
    let size = tree.size().to_int_size();
    let mut pixmap = Pixmap::new(size.width(), size.height()).ok_or_else(|| {
        failed(
            "render the picture",
            &format!("{}×{} pixels", size.width(), size.height()),
        )
    })?;
    pixmap.fill(Color::WHITE);
    resvg::render(&tree, Transform::identity(), &mut pixmap.as_mut());
    pixmap
        .encode_png()
        .map_err(|e| failed("encode the PNG", &e))
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" width="40" height="30"><rect x="10" y="10" width="10" height="10" fill="#ff0000"/><text x="2" y="28" font-family="sans-serif" font-size="10">α = 1</text></svg>"##;

    fn decode(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
        let mut reader = png::Decoder::new(io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        (info.width, info.height, buf)
    }

    #[test]
    fn sans_serif_text_is_set_in_a_sans_serif_face_when_there_is_one() {
        let dejavu = [
            "DejaVu Serif",
            "DejaVu Sans Mono",
            "DejaVu Sans Bold",
            "DejaVu Sans",
        ];
        assert_eq!(sans_family(&dejavu), Some("DejaVu Sans"));
        let other = ["Foo Serif", "Bar Sans Mono", "Baz Sans"];
        assert_eq!(sans_family(&other), Some("Baz Sans"));
        assert_eq!(sans_family(&["Only Serif"]), Some("Only Serif"));
        assert_eq!(sans_family(&[]), None);
    }

    #[test]
    fn a_picture_is_produced_without_any_font() {
        let bytes = render_png(DOC, Arc::new(fontdb::Database::new())).unwrap();
        let (w, h, rgba) = decode(&bytes);
        assert_eq!((w, h), (40, 30));
        let at = |x: usize, y: usize| &rgba[4 * (y * 40 + x)..4 * (y * 40 + x) + 4];
        assert_eq!(at(15, 15), [255, 0, 0, 255], "the square is painted");
        assert_eq!(at(35, 5), [255, 255, 255, 255], "on white");
    }
}
