"""A rendered PNG as raw RGB pixels, for the tests that look at the program's screenshots."""
import subprocess


def read_ppm(png):
    """(width, height, bytes): the PNG through ImageMagick's convert as binary PPM (P6, 8 bit)."""
    data = subprocess.run(["convert", png, "ppm:-"], check=True, capture_output=True).stdout
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P6" and fields[3] == b"255", fields
    return int(fields[1]), int(fields[2]), data[pos + 1:]
