// Files from strangers, opened as a user would open them: every rejection is a `file:line` message
// with exit 1, no crash, no runaway memory, and nothing read from outside the folders an effect may
// read. One case per defect class found by fuzzing (issue #9); tests/fuzz replays the raw inputs.
#include <doctest/doctest.h>

#include "hostile_support.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using fxview::test::Result;
using fxview::test::run;
using fxview::test::temp_path;
namespace fs = std::filesystem;

using fxview::test::folder;
using fxview::test::has;
using fxview::test::kShaders;
using fxview::test::kTechnique;
using fxview::test::write;

TEST_CASE("an OBJ face naming a normal or uv that no line defines is an error at its line") {
    const std::string dir = folder("obj");
    const std::string obj = write(dir + "/missing-normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n");
    const Result r = run("render --mesh " + obj + " --size 32x32 --out " + dir + "/out.png");
    CHECK(r.exit_code == 1);
    CHECK(has(r.err, "missing-normal.obj:4: face refers to normal 1, but the file defines 0"));
    const std::string uv = write(dir + "/missing-uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n");
    const Result r2 = run("render --mesh " + uv + " --size 32x32 --out " + dir + "/out.png");
    CHECK(r2.exit_code == 1);
    CHECK(has(r2.err, "missing-uv.obj:5: face refers to texture coordinate 2, but the file defines 1"));
    const std::string nan = write(dir + "/nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    const Result r3 = run("render --mesh " + nan + " --size 32x32 --out " + dir + "/out.png");
    CHECK(r3.exit_code == 1);
    CHECK(has(r3.err, "nan.obj:2: 'nan' is not a finite number"));
    // mtllib is ignored: an OBJ cannot make fxview open another file, and the mesh still renders.
    const std::string mtl = write(dir + "/mtl.obj", "mtllib ../../../../../../../../etc/passwd\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Result r4 = run("render --mesh " + mtl + " --size 32x32 --out " + dir + "/out.png");
    CHECK(r4.exit_code == 0);
    CHECK(!has(r4.err, "root"));
}

TEST_CASE("a line of 30 000 blanks, a 400 kB word and deep includes are handled without recursion") {
    const std::string dir = folder("scanner");
    const std::string blanks = write(dir + "/blanks.fx", std::string(30000, ' ') + "\n#include \"lib.glsl\"" + std::string(30000, ' ') +
                                                             "\n" + kShaders + kTechnique);
    write(dir + "/lib.glsl", "float helper() { return 1.0; }\n");
    const Result ok = run("check " + blanks);
    CHECK(ok.exit_code == 0);
    CHECK(has(ok.out, "blanks.fx: ok"));

    const std::string word = write(dir + "/word.fx", "uniform float " + std::string(400000, 'x') + ";\n" + kShaders + kTechnique);
    const Result w = run("check " + word);
    CHECK(w.exit_code == 1);
    CHECK(has(w.out, "word.fx:1: a word of 400000 characters (at most 1024)"));
    CHECK(w.out.size() < 2000);  // the message quotes no megabyte

    // A chain of 7000 includes: stopped at the documented depth, named at the include that is too deep.
    for (int i = 0; i < 7000; ++i) write(dir + "/chain" + std::to_string(i) + ".glsl", "#include \"chain" + std::to_string(i + 1) + ".glsl\"\n");
    const std::string chain = write(dir + "/chain.fx", "#include \"chain0.glsl\"\n" + kShaders + kTechnique);
    const Result c = run("check " + chain);
    CHECK(c.exit_code == 1);
    CHECK(has(c.out, "chain31.glsl:1: #include nested deeper than 32 levels"));
    CHECK(run("check --limit include-depth=40 " + chain).out.find("nested deeper than 40 levels") != std::string::npos);

    // Includes that multiply (each file includes the next one twice) stop at the source budget.
    for (int i = 0; i < 30; ++i)
        write(dir + "/twice" + std::to_string(i) + ".glsl", "#include \"twice" + std::to_string(i + 1) + ".glsl\"\n#include \"twice" +
                                                               std::to_string(i + 1) + ".glsl\"\n// " + std::string(100, 'x') + "\n");
    write(dir + "/twice30.glsl", "// " + std::string(100, 'x') + "\n");
    const Result t = run("check " + write(dir + "/twice.fx", "#include \"twice0.glsl\"\n" + kShaders + kTechnique));
    CHECK(t.exit_code == 1);
    CHECK(has(t.out, "exceeds the budget source-bytes"));
}

TEST_CASE("array sizes are checked before anything is allocated") {
    const std::string dir = folder("arrays");
    for (const std::string size : {"1000000000", "100000000", "3e9", "1e300"}) {
        CAPTURE(size);
        const Result r = run("check " + write(dir + "/array.fx", "uniform float a[" + size + "];\n" + kShaders + kTechnique));
        CHECK(r.exit_code == 1);
        CHECK(has(r.out, "array.fx:1: array of " + size + " elements exceeds the budget array-elements = 65536"));
    }
    const Result half = run("check " + write(dir + "/half.fx", "uniform float a[2.5];\n" + kShaders + kTechnique));
    CHECK(has(half.out, "half.fx:1: array size must be a positive whole number"));
    const Result raised = run("list --limit array-elements=200000 " + write(dir + "/big.fx", "uniform float a[100000];\n" + kShaders + kTechnique));
    CHECK(raised.exit_code == 0);
    CHECK(run("list --limit array-elements=lots " + dir + "/big.fx").exit_code == 2);
    CHECK(run("list --limit frobs=1 " + dir + "/big.fx").exit_code == 2);
}

TEST_CASE("texture headers that claim huge sizes are refused before decoding") {
    const std::string dir = folder("textures");
    // A PNG whose IHDR claims 16000x16000 (1 GB decoded) in a few hundred bytes.
    const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                 0, 0, 0x3e, 0x80, 0, 0, 0x3e, 0x80, 8, 6, 0, 0, 0, 0, 0, 0, 0};
    std::ofstream(dir + "/huge.png", std::ios::binary).write(reinterpret_cast<const char*>(png), sizeof png);
    const std::string effect = "texture Tex < string ResourceName = \"huge.png\"; >;\nuniform sampler2D S < string Texture = \"Tex\"; >;\n";
    const Result r = run("check " + write(dir + "/huge.fx", effect + kShaders + kTechnique));
    CHECK(r.exit_code == 1);
    CHECK(has(r.out, "huge.fx:1: texture Tex:"));
    CHECK(has(r.out, "huge.png: decoded image of 1024000000 exceeds the budget texture-bytes"));

    // FTXT's header claims as much; it is checked before any texel line is read.
    write(dir + "/huge.ftxt", "16384 16384\n1;2;3;4\n");
    const Result f = run("check " + write(dir + "/ftxt.fx", "texture Tex < string ResourceName = \"huge.ftxt\"; >;\n" + kShaders + kTechnique));
    CHECK(has(f.out, "huge.ftxt:1: FTXT texture of 4294967296 exceeds the budget texture-bytes"));

    // A 1x1 DDS with 15 mip levels: a full chain of a 1x1 texture has one.
    std::string dds = "DDS ";
    const auto word = [&](std::uint32_t v) { dds.append(reinterpret_cast<const char*>(&v), 4); };
    word(124), word(0x1 | 0x2 | 0x4 | 0x1000 | 0x20000), word(1), word(1), word(0), word(0), word(15);
    for (int i = 0; i < 11; ++i) word(0);
    word(32), word(0x41), word(0), word(32), word(0xff), word(0xff00), word(0xff0000), word(0xff000000);
    word(0x1000), word(0), word(0), word(0), word(0);
    dds += std::string(64, '\xff');
    write(dir + "/mips.dds", dds);
    const Result d = run("check " + write(dir + "/dds.fx", "texture Tex < string ResourceName = \"mips.dds\"; >;\n" + kShaders + kTechnique));
    CHECK(d.exit_code == 1);
    CHECK(has(d.out, "mips.dds: DDS declares 15 mip levels, but a 1x1 texture has at most 1"));
}

TEST_CASE("an effect reads only below its folder and the search roots; --allow-path widens that") {
    const std::string dir = folder("policy"), outside = folder("policy-outside");
    const Result passwd = run("check " + write(dir + "/passwd.fx", "#include \"/etc/passwd\"\n" + kShaders + kTechnique));
    CHECK(passwd.exit_code == 1);
    CHECK(has(passwd.out, "passwd.fx:1: included file '/etc/passwd' is refused by the file-access policy"));
    CHECK(!has(passwd.out + passwd.err, "root"));  // nothing of the file is printed
    const Result traversal = run("check " + write(dir + "/up.fx", "#include \"../../../../../../../../../etc/passwd\"\n" + kShaders + kTechnique));
    CHECK(has(traversal.out, "refused by the file-access policy"));
    CHECK(!has(traversal.out + traversal.err, "root"));

    // A texture outside, by absolute path and through a symbolic link inside the folder.
    std::filesystem::copy_file(std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/../textures/checker.png", outside + "/secret.png");
    const std::string absolute = write(dir + "/absolute.fx", "texture Tex < string ResourceName = \"" + outside + "/secret.png\"; >;\n" +
                                                                  kShaders + kTechnique);
    const Result refused = run("check " + absolute);
    CHECK(refused.exit_code == 1);
    CHECK(has(refused.out, "absolute.fx:1: texture Tex: texture file '" + outside + "/secret.png' is refused by the file-access policy"));
    const Result allowed = run("check --allow-path " + outside + " " + absolute);
    CHECK(allowed.exit_code == 0);
    fs::create_symlink(outside + "/secret.png", dir + "/link.png");
    const Result link = run("check " + write(dir + "/link.fx", "texture Tex < string ResourceName = \"link.png\"; >;\n" + kShaders + kTechnique));
    CHECK(link.exit_code == 1);
    CHECK(has(link.out, "is refused by the file-access policy"));
    // The shipped effects read their includes and textures from the search roots as before.
    CHECK(run("check " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/examples/textured.fx").exit_code == 0);
    CHECK(run("check --allow-path /no/such/folder " + absolute).exit_code == 2);
}

TEST_CASE("diagnostics name the file and line: NUL bytes, a missing ';', long names, several files") {
    const std::string dir = folder("diagnostics");
    const Result nul = run("check " + write(dir + "/nul.fx", "float x = 1.0;\n" + std::string("float y = 2.0;\0\n", 16) + kShaders + kTechnique));
    CHECK(nul.exit_code == 1);
    CHECK(has(nul.out, "nul.fx:2: the line holds a NUL byte"));
    const Result semicolon = run("check " + write(dir + "/semicolon.fx", kShaders + "const float x = 1.0\n" + kTechnique));
    CHECK(semicolon.exit_code == 1);
    CHECK(has(semicolon.out, "semicolon.fx:4: expected ';' before 'technique'"));
    const Result long_name = run("check " + write(dir + "/long.fx", "#include \"" + std::string(5000, 'a') + "\"\n" + kShaders + kTechnique));
    CHECK(long_name.exit_code == 1);
    CHECK(has(long_name.out, "long.fx:1: #include names a file of 5000 characters (at most 1024)"));
    // check goes on after a broken file and reports every one.
    const std::string good = write(dir + "/good.fx", kShaders + kTechnique);
    const Result both = run("check " + dir + "/semicolon.fx " + dir + "/missing.fx " + good);
    CHECK(both.exit_code == 1);
    CHECK(has(both.out, "semicolon.fx:4:"));
    CHECK(has(both.out, "missing.fx:0: cannot open effect file"));
    CHECK(has(both.out, "good.fx: ok"));
    CHECK(has(both.out, "1 of 3 effects ok"));
}

TEST_CASE("malformed presets, grids, MERL headers and spectra are rejected with file:line") {
    const std::string dir = folder("data");
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const Result json = run("render " + effect + " --size 16x16 --out " + dir + "/o.png --preset " + write(dir + "/bad.json", "{\n \"parameters\": {\n  \"Roughness\": ]\n}}"));
    CHECK(json.exit_code == 1);
    CHECK(has(json.err, "bad.json:3: not a valid JSON preset"));
    CHECK(!has(json.err, "[json.exception"));
    const Result type = run("render " + effect + " --size 16x16 --out " + dir + "/o.png --preset " +
                            write(dir + "/type.json", "{\n \"parameters\": {\n  \"Roughness\": \"rough\"\n}}"));
    CHECK(has(type.err, "type.json:3: preset value of Roughness must be a number"));

    const Result garbage = run("fit " + write(dir + "/garbage.csv", "theta_in_deg,theta_out_deg,phi_out_deg,r,g,b\n0,0,0,0.25garbage,1,1\n"));
    CHECK(garbage.exit_code == 1);
    CHECK(has(garbage.err, "garbage.csv:2: '0.25garbage' is not a finite number"));

    std::string merl(12, '\0');
    const std::int32_t dims[3] = {1 << 30, 1 << 30, 1 << 30};
    std::memcpy(merl.data(), dims, sizeof dims);
    const Result overflow = run("fit " + write(dir + "/overflow.binary", merl + std::string(64, '\0')));
    CHECK(overflow.exit_code == 1);
    CHECK(has(overflow.err, "overflow.binary: not a MERL BRDF"));
    CHECK(!has(overflow.err, "1073741824"));  // a file's first bytes never reach a message

    const std::string cgats = "CGATS.17\nSPECTRAL_START_NM 380\nSPECTRAL_END_NM 780\nSPECTRAL_BANDS 1e300\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_380 SPEC_780\n"
                              "END_DATA_FORMAT\nBEGIN_DATA\n\"A\" 1 2\nEND_DATA\n";
    const Result bands = run("spectra xyz " + write(dir + "/bands.sp", cgats));
    CHECK(bands.exit_code != 0);
    CHECK(has(bands.err, "bands.sp:4: SPECTRAL_BANDS needs a whole number in 2..100000"));
    const Result nan = run("spectra xyz " + write(dir + "/nan.csv", "nm,value\n400,nan\n700,1\n"));
    CHECK(nan.exit_code != 0);
    CHECK(has(nan.err, "nan.csv:2: expected 'nm,value' (finite numbers)"));
}

TEST_CASE("render targets, polygon fans, endless spectra and odd --set values stay within the budgets") {
    const std::string dir = folder("more");
    std::string targets;
    for (int i = 0; i < 50; ++i)
        targets += "texture RT" + std::to_string(i) + " : RENDERCOLORTARGET < int2 Dimensions = {8192, 8192}; string Format = \"32F\"; >;\n";
    const std::string many = write(dir + "/targets.fx", targets + kShaders + kTechnique);
    const Result r = run("render " + many + " --size 32x32 --out " + dir + "/o.png");
    CHECK(r.exit_code == 1);
    CHECK(has(r.err, "targets.fx:1: render target RT0: size 1073741824 exceeds the budget texture-bytes"));
    CHECK(run("check " + many).exit_code == 1);  // fixed Dimensions are checked when the effect loads
    const std::string ratio = write(dir + "/ratio.fx", "texture R : RENDERCOLORTARGET < float2 ViewportRatio = {64, 64}; >;\n" + kShaders + kTechnique);
    const Result r2 = run("render " + ratio + " --size 256x256 --out " + dir + "/o.png");
    CHECK(r2.exit_code == 1);
    CHECK(has(r2.err, "ratio.fx:1: render target R: size 4294967296 exceeds the budget texture-bytes"));

    std::string fan = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 2000; ++i) fan += " " + std::to_string(i % 3 + 1);
    const Result f = run("render --mesh " + write(dir + "/fan.obj", fan + "\n") + " --size 16x16 --out " + dir + "/o.png");
    CHECK(f.exit_code == 1);
    CHECK(has(f.err, "fan.obj:4: a face with more than 1024 corners"));

    std::string rows = "CGATS.17\nSPECTRAL_START_NM 380\nSPECTRAL_END_NM 780\nSPECTRAL_BANDS 2\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_380 SPEC_780\n"
                       "END_DATA_FORMAT\nBEGIN_DATA\n";
    for (int i = 0; i < 5000; ++i) rows += "\"A\" 1 2\n";
    const Result s = run("spectra xyz " + write(dir + "/rows.sp", rows + "END_DATA\n"));
    CHECK(s.exit_code != 0);
    CHECK(has(s.err, "rows.sp:4105: more than 4096 data sets in one file"));

    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/debug.fx";
    CHECK(run("render " + effect + " --set Ambient=nan --size 8x8 --out " + dir + "/o.png").exit_code == 2);
    const Result huge = run("render " + effect + " --technique " + std::string(100000, 'T') + " --size 8x8 --out " + dir + "/o.png");
    CHECK(huge.exit_code == 2);
    CHECK(huge.err.size() < 9000);  // the name is not echoed in full
}
