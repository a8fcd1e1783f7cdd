/* 24-bit uncompressed BMP, the course's output format: a BITMAPFILEHEADER,
 * a BITMAPINFOHEADER, then rows bottom to top in BGR order, each padded to
 * a multiple of four bytes. */
#include <errno.h>
#include <stdint.h>
#include <string.h>

#include "whitted/image.h"

static void put_le16(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static void put_le32(uint8_t *p, uint32_t v)
{
	put_le16(p, v & 0xffff);
	put_le16(p + 2, v >> 16);
}

int image_write_bmp(const struct image *img, FILE *f, struct diag *d)
{
	size_t row_bytes = ((size_t)img->width * 3 + 3) & ~(size_t)3;
	uint8_t header[54] = { 'B', 'M' };
	uint8_t row_buf[4 * 32768 + 4];
	int y, x;

	if (row_bytes > sizeof(row_buf) || row_bytes * (size_t)img->height > 0xffffffffu - 54)
		return diag_fail(d, RT_E_INVALID, "image too large for BMP");
	put_le32(header + 2, (uint32_t)(54 + row_bytes * (size_t)img->height));
	put_le32(header + 10, 54);
	put_le32(header + 14, 40);
	put_le32(header + 18, (uint32_t)img->width);
	put_le32(header + 22, (uint32_t)img->height);
	put_le16(header + 26, 1);
	put_le16(header + 28, 24);
	put_le32(header + 34, (uint32_t)(row_bytes * (size_t)img->height));
	put_le32(header + 38, 2835);	/* 72 dpi */
	put_le32(header + 42, 2835);
	if (fwrite(header, 1, sizeof(header), f) != sizeof(header))
		goto out_io;
	memset(row_buf, 0, row_bytes);
	for (y = img->height - 1; y >= 0; y--) {
		const uint8_t *src = img->pixels + (size_t)y * (size_t)img->width * 3;
		for (x = 0; x < img->width; x++) {
			row_buf[3 * x + 0] = src[3 * x + 2];
			row_buf[3 * x + 1] = src[3 * x + 1];
			row_buf[3 * x + 2] = src[3 * x + 0];
		}
		if (fwrite(row_buf, 1, row_bytes, f) != row_bytes)
			goto out_io;
	}
	return 0;
out_io:
	return diag_fail(d, RT_E_IO, "cannot write BMP: %s", strerror(errno));
}
