#[test]
fn probe() {
    for f in ["out/simple-reference.exr", "out/simple-multilayer.exr", "out/simple-gather.exr"] {
        let (layers, _) = dof::io::read_layered_exr(format!("../{f}")).unwrap();
        let (img, depth) = layers.front();
        let y = 180;
        let row: Vec<String> = (426..440).map(|x| { let p = img.get(x, y); format!("{:.2}/{:.2}", p[0], p[1]) }).collect();
        println!("{f}: {}", row.join(" "));
        let row: Vec<String> = (426..440).map(|x| format!("{:.2}", depth[(y * 640 + x) as usize])).collect();
        println!("   z: {}", row.join(" "));
    }
}
