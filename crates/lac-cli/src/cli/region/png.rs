//! Encoding the region map as an 8-bit grayscale PNG: white drawable, black not.

use std::io::Write;

/// Write `rows` (all of the same length) as a grayscale PNG to `out`.
pub(crate) fn write_png(rows: &[Vec<bool>], out: &mut dyn Write) -> std::io::Result<()> {
    let height = rows.len() as u32;
    let width = rows.first().map_or(0, Vec::len) as u32;
    let pixels: Vec<u8> = rows
        .iter()
        .flatten()
        .map(|&drawable| if drawable { 255 } else { 0 })
        .collect();
    let mut encoder = png::Encoder::new(out, width, height);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&pixels)?;
    writer.finish()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_png_decodes_to_the_same_pixels() {
        let rows = vec![vec![true, false, true], vec![false, false, true]];
        let mut bytes = Vec::new();
        write_png(&rows, &mut bytes).unwrap();
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (3, 2));
        assert_eq!(&buf[..6], &[255, 0, 255, 0, 0, 255]);
    }
}
