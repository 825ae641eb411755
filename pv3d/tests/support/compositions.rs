//! Compositions written to a temporary folder and loaded, for the composition tests.

use std::fs;
use std::path::{Path, PathBuf};

use pv3d::composition::{Composition, ConfigError, FoundDevice, ParserRegistry};

pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent).unwrap();
    }
    fs::write(&path, text).unwrap();
    path
}

pub fn device(port: u16, addr: &str, driver: &str) -> FoundDevice {
    FoundDevice {
        host: "localhost".into(),
        port,
        addr: addr.parse().unwrap(),
        driver: driver.into(),
    }
}

/// The paper's Fig. 4 composition, with the Fig. 5 template in a subfolder.
pub fn paper_example(dir: &Path) -> PathBuf {
    write(
        dir,
        "templates/laser.pv3d.xml",
        r#"<plugin library="libpv3d_laser" id="laser">
  <playerDeviceMask host="localhost" port="6665" interface="laser" index="0"/>
  <parentNode interface="position2d" index="0"/>
  <fillLaserCspace>1</fillLaserCspace>
  <drawLaserCspace>1</drawLaserCspace>
</plugin>"#,
    );
    write(
        dir,
        "paper.xml",
        r#"<pv3d xmlns:pv3d="http://miarn.sf.net" xmlns:xi="http://www.w3.org/2001/XInclude">
  <handlers>
    <playerClient host="localhost" port="6665"/>
    <playerDeviceMask interface="laser">
      <xi:include href="templates/laser.pv3d.xml"/>
    </playerDeviceMask>
  </handlers>
  <plugin library="libpv3d_lights"/>
  <plugin library="libpv3d_ground"/>
</pv3d>"#,
    )
}

pub fn load(paths: &[PathBuf]) -> Result<Composition, ConfigError> {
    Composition::load_files(paths, &ParserRegistry::default())
}
