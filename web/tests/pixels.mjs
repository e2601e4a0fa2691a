// Counts the drawn hand's, wood's and force arrows' pixels in the page's canvas (the 3D view,
// in an immersive session both eyes' views), by hue: the hand's skin (hue 5–28°, the page's
// skin is 16°), the cube's wood (33–48°, the page's wood is 39°), each saturated enough that
// neither the grey ground nor the blue-grey background counts, and the force arrows' red
// (within 4° of 0°, nearly fully saturated: unlit, drawn over everything).
export async function colours(page) {
  return page.evaluate(() => {
    const source = document.getElementById('view');
    const canvas = document.createElement('canvas');
    canvas.width = source.width;
    canvas.height = source.height;
    const context = canvas.getContext('2d');
    context.drawImage(source, 0, 0);
    const { data } = context.getImageData(0, 0, canvas.width, canvas.height);
    let skin = 0;
    let wood = 0;
    let red = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i] / 255, data[i + 1] / 255, data[i + 2] / 255];
      const max = Math.max(r, g, b);
      const min = Math.min(r, g, b);
      if (max < 0.15 || max === min || max !== r) continue;
      const saturation = (max - min) / max;
      const hue = 60 * ((g - b) / (max - min));
      if (Math.abs(hue) <= 4 && saturation > 0.85) red++;
      else if (hue >= 5 && hue <= 28 && saturation > 0.15) skin++;
      else if (hue >= 33 && hue <= 48 && saturation > 0.4) wood++;
    }
    return { skin, wood, red };
  });
}
