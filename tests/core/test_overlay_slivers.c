/* Sub-polygon pairs on which the overlay construction gave up ("a face
 * could not be triangulated in every geometry"), found by cm_font_soak
 * (bench/font_soak.c, seed 1) on glyph pairs from Debian's fonts: the
 * pieces the partition handed to its fallback, as bit-exact hex floats.
 * Most are quadrilaterals whose four vertices in one geometry are arc-length
 * samples along a straight glyph edge, turned by a rotation: a sliver far
 * thinner than the spacing of doubles (twice its area ~1e-18 for sides
 * ~0.1), whose one Steiner vertex the rounded crossing put outside it.
 * offset_1e15 is the piece of cm_gen_pairs' L/T pair (n = 160) scaled by
 * 100 and shifted by 1e15, where doubles are 1/8 apart.
 * Each must now give a valid result, checked exactly from the public
 * arrays (result_check.h), by the overlay alone and by the default
 * pipeline; except the few still open below, which must at least fail
 * cleanly, saying which triangles stay inverted. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "compatmesh/compatmesh.h"
#include "result_check.h"

typedef struct {
    const char *name;
    size_t n;
    double xy[2][16];
} sliver_case;

static const sliver_case cases[] = {
    {"soak_0", 4, {{0x1.0a78c3e138819p-1, 0x1.08a3ce3e3b8bp-4, 0x1.28fb8b15e9787p-1, 0x1.b678623ec34cp-5, 0x1.24547b9e93db4p-1, 0x1.31c752379d1d4p-4, 0x1.184af1ba390ecp-1, 0x1.0c9e89aa85b2dp-4},
     {-0x1.04c5b89306a07p-3, -0x1.b52e8f7a28ba1p-2, -0x1.a7030cef55ddcp-4, -0x1.fdbec2405d7p-2, -0x1.c7db31c4b149ep-4, -0x1.e58eaecd320e6p-2, -0x1.f28dc15d93774p-4, -0x1.c61d00d738cacp-2}}},
    {"soak_1", 4, {{-0x1.adc6fc5b7a51bp-2, 0x1.01ce3b0406164p-4, -0x1.b217eb4c37d67p-2, 0x1.ede44504118dp-5, -0x1.b668da3cf55b4p-2, 0x1.d82c140016ed8p-5, -0x1.ab53fa7d7fa5fp-2, 0x1.d2796ca794cd4p-5},
     {-0x1.d0dd5b641d1ecp-2, -0x1.f4517e26b61bdp-2, -0x1.d2a6d471f346ap-2, -0x1.e24f9ae82c282p-2, -0x1.d4704d1aaa1f7p-2, -0x1.d04dbba4a0dbcp-2, -0x1.cdab991f4bae7p-2, -0x1.0a40f70e3c8dep-1}}},
    {"soak_2", 4, {{0x1.e376731a3bbd5p-3, -0x1.3d7852702a616p-2, 0x1.f1e7e2ae2994ep-3, -0x1.38194f5cf97bep-2, 0x1.002ca9210bb63p-2, -0x1.32ba4c49c8966p-2, 0x1.076560eb02a1fp-2, -0x1.2d5b493697b0ep-2},
     {0x1.952a3ef320be4p-1, -0x1.1dfe1aa8ae517p-2, 0x1.9e6ccb9df88fep-1, -0x1.148e0b26e6257p-2, 0x1.a7af5b17b9e1ep-1, -0x1.0b1dfc51c86ap-2, 0x1.b08ff422fee67p-1, -0x1.005ad56b9a1b1p-2}}},
    {"soak_3", 4, {{-0x1.aeb1125a8aa46p-3, -0x1.2037a341eaea2p-2, -0x1.92eb73387d57fp-3, -0x1.14774ccbdfd9dp-2, -0x1.7725d416700b8p-3, -0x1.08b6f655d4c98p-2, -0x1.5b602ed90fd84p-3, -0x1.f9ed3a949411p-3},
     {0x1.6232f15c166edp-2, -0x1.04f6d2730e946p-2, 0x1.63d15935a19f5p-2, -0x1.f20c7284f9d04p-3, 0x1.656fc10f2ccfdp-2, -0x1.da2b4023d677bp-3, 0x1.670e28e8b8005p-2, -0x1.c24a0dc2b31f2p-3}}},
    {"soak_4", 4, {{0x1.89193d4602d41p+15, -0x1.f389789d24c9ep+15, 0x1.891a5ce0de866p+15, -0x1.f3a7a04216e22p+15, 0x1.891abcbf27c1dp+15, -0x1.f3b1ad79123f9p+15, 0x1.891b1c9d70fd4p+15, -0x1.f3bbbab00d9cfp+15},
     {-0x1.5ed2de697d7f6p-3, 0x1.39302b4d3170ap-4, -0x1.52e8ff4e3bc9ep-2, 0x1.9261b2e6c0e6p-6, -0x1.867120a422cc6p-2, -0x1.77f8edf7801p-10, -0x1.bb14457d65837p-2, -0x1.9c905fd1bc758p-6}}},
    {"soak_5", 4, {{-0x1.ca3dfb0593ca8p-5, 0x1.63750667023cfp-3, 0x1.4c6935f80ff86p-6, 0x1.0d3a23f67558bp-3, -0x1.c25642f3e5afep-7, 0x1.8afc8f5503f02p-3, -0x1.33c6cb9bd6dep-8, 0x1.3fa4498085321p-3},
     {0x1.0f6729fc2eaaap-2, -0x1.a7c6da56f6a24p-3, 0x1.6f4065c0777b4p-4, -0x1.1eb8035382fabp-4, 0x1.c502ca1ec231fp-3, -0x1.61ac22f095fabp-3, 0x1.f1e88f0b8fc3ap-3, -0x1.84b97ea3c64e8p-3}}},
    {"soak_6", 4, {{0x1.2241ff51ae2e6p-4, -0x1.e779dd32b48f7p-6, 0x1.14f027d4eddcep-4, -0x1.1f7cc25d91993p-5, 0x1.0e473c168db42p-4, -0x1.355cac3fad41fp-5, 0x1.079e50582d8b6p-4, -0x1.4b3c9621c8eabp-5},
     {-0x1.773df6dac2432p-1, -0x1.acd7cd6a96ba4p-3, -0x1.6da79e92e9bcfp-1, -0x1.d58a721b6590dp-3, -0x1.68dc71bf6d44dp-1, -0x1.e9e3c75d1037fp-3, -0x1.6411464b1136cp-1, -0x1.fe3d16cc34675p-3}}},
    {"soak_7", 4, {{0x1.b1405647851f8p-18, 0x1.16897a1e4fd1ep-16, 0x1.b24ddc0262b4ap-18, 0x1.16956343fbcc8p-16, 0x1.b35b617b2ab27p-18, 0x1.16a14c66bc27fp-16, 0x1.b468e6f3f2b04p-18, 0x1.16ad35897c836p-16},
     {-0x1.b6aecaa9db9cep-2, -0x1.57caf93715e74p-2, -0x1.b3a4b880c8376p-2, -0x1.4a9d0b2274049p-2, -0x1.b09aa657b4d1ep-2, -0x1.3d6f1d0dd221ep-2, -0x1.ad90942ea16c7p-2, -0x1.30412ef9303f3p-2}}},
    {"soak_8", 4, {{0x1.ceceb52461a99p-3, -0x1.4d87d49022daap-1, 0x1.3662eebebe046p-2, -0x1.299f3b14afe04p-1, 0x1.14291ea749b8cp-2, -0x1.392eb040671e8p-1, 0x1.fb9079397a8d8p-3, -0x1.435b426844fc9p-1},
     {0x1.11918242b2aedp-1, -0x1.3cdc07887d25bp-1, 0x1.56909e3b9550ap-1, -0x1.4b7c52ebc1d2ep-1, 0x1.930b31cb55075p-1, -0x1.b1906a37fc5f5p-2, 0x1.4e1d7d144a341p-1, -0x1.3ffa21b7a0f62p-1}}},
    {"soak_9", 4, {{-0x1.3c080d0dfa50bp-1, 0x1.5ea240658867ap-4, -0x1.55a08f08d9abp-1, 0x1.91b0c2c1acb04p-3, -0x1.4234648cea7e5p-1, 0x1.fb98b495acacp-7, -0x1.42d4b85a3db8fp-1, 0x1.056dc79598915p-4},
     {0x1.f2cbc35f63f7p-7, -0x1.9bea02b437972p-2, 0x1.52e6be8f623fep-4, -0x1.072b6902280dap-1, -0x1.2fb49a0abc898p-6, -0x1.62b39cc263379p-2, -0x1.0020b2b264893p-6, -0x1.679f7d6dafc47p-2}}},
    {"soak_10", 4, {{-0x1.fd737c5433cc8p-6, 0x1.fcbdf7b7729a8p-3, -0x1.33bcbc7c77efp-5, 0x1.04c6ad851d7c3p-2, -0x1.68bfbaced5f7cp-5, 0x1.0b2e5f2e81ab2p-2, -0x1.9dc2b92134008p-5, 0x1.119610d7e5dap-2},
     {0x1.6dbaf9baa00e3p-1, -0x1.678a086f1153p-4, 0x1.60234cd5ed1b3p-1, -0x1.2e4f84b5f7c84p-4, 0x1.5e7bba1fa6827p-1, -0x1.bda42749b6c44p-4, 0x1.59dc6bba2f6e4p-1, -0x1.2463e8281a3a7p-3}}},
    {"soak_11", 4, {{0x1.0fbb9a0cfdbfep-3, -0x1.60d6a20157fbdp-1, 0x1.4ebd3f2f31a8fp-4, -0x1.5bdaa98f9e49fp-1, 0x1.b701f8b705801p-4, -0x1.5e581184878c8p-1, 0x1.db916719a8666p-4, -0x1.5f3790e36a19ep-1},
     {0x1.1df9bf2c7435p+10, -0x1.3c5385282d292p+11, 0x1.1acf52c00d0c4p+10, -0x1.37f5eaaa5ee4p+11, 0x1.211b7b5d030ecp+10, -0x1.40b2ae4c862dap+11, 0x1.1df66441e575fp+10, -0x1.3c541fec87daep+11}}},
    {"soak_12", 4, {{-0x1.1567c182624a8p-2, 0x1.1b0b06393190cp-3, -0x1.20d0251a27df3p-2, 0x1.14e32efb5b974p-3, -0x1.2c388c8e93a3fp-2, 0x1.0ebb55a80c174p-3, -0x1.e03de296f924ap-3, 0x1.2f2966e14939dp-3},
     {-0x1.515d2d5f2122fp-1, 0x1.fe04eeeeb2eb8p-4, -0x1.4af0231e3b78cp-1, 0x1.d3347af0f3208p-4, -0x1.448318dd55ceap-1, 0x1.a86406f33355cp-4, -0x1.470fbf67f7c2fp-1, 0x1.093a3a2891a99p-3}}},
    {"soak_13", 4, {{0x1.497db43c3f62cp-1, 0x1.0ff669fe29709p-3, 0x1.440f66dd26479p-1, 0x1.cb3892362428ap-4, 0x1.571174c05214dp-1, 0x1.79d7b5179f317p-3, 0x1.477fae4790747p-1, 0x1.006d0cdcc1813p-3},
     {0x1.d9525497ed385p-3, -0x1.7cf8b61d5111dp-2, 0x1.ad417ef0f545p-3, -0x1.86d5a05da6de5p-2, 0x1.23be3ad69e07ep-2, -0x1.64506a08e73e8p-2, 0x1.2122a34678c5ep-2, -0x1.657b427a0f7e8p-2}}},
    {"soak_14", 4, {{0x1.803eb394dcc74p-2, -0x1.024cdb30bfc6p-1, 0x1.a435afa4749ddp-2, -0x1.e32f2613ab0b6p-2, 0x1.7042b407a2947p-2, -0x1.09b9df6b2878ep-1, 0x1.771979880b66fp-2, -0x1.068c84a55b44fp-1},
     {0x1.1a96acdd2a354p-6, 0x1.156bc4757fb85p-1, 0x1.7a130e45f908p-4, 0x1.3005c9503afcbp-1, 0x1.b120d2c039ep-11, 0x1.400a7dd0ed357p-1, 0x1.2e7f22ce81c0ep-5, 0x1.28f6d92841785p-1}}},
    {"soak_15", 4, {{0x1.66c9087313cc7p-2, -0x1.144b51c7a7b45p-1, 0x1.a196dbccd6198p-2, -0x1.0bca72943cef4p-1, 0x1.8f73eb28488e4p-2, -0x1.01d039363bb54p-1, 0x1.82433a7313cc8p-2, -0x1.0efbd310b5678p-1},
     {0x1.c0fa7598b400ep-2, -0x1.17e0c1d7adf9ep-1, 0x1.74f43cc54cab3p-2, -0x1.3d2b527a4ab42p-1, 0x1.8e4ba50bc4726p-2, -0x1.30bd224416761p-1, 0x1.af3d46342cf56p-2, -0x1.209449fd9f589p-1}}},
    {"soak_16", 4, {{-0x1.ee9a7265ea474p-3, -0x1.4446488b0d53ep-2, -0x1.ac9c502ee1c6ap-3, -0x1.63c21a70e664dp-2, -0x1.c4b76be6894f6p-3, -0x1.38476b9416388p-2, -0x1.d3dd84f31f3abp-3, -0x1.462b7712206ffp-2},
     {0x1.c7a0edef633f8p-2, -0x1.f0c87d614264p-2, 0x1.3dfb7c3e76db2p-2, -0x1.cc0c3693bdf6ep-2, 0x1.a04d17b2f1b83p-2, -0x1.e6498e0444857p-2, 0x1.b3f702d12a7bep-2, -0x1.eb8905b2c374cp-2}}},
    {"soak_17", 4, {{-0x1.4903315b3c7cep-3, 0x1.c218a11ae915fp-3, -0x1.397e0fcd2aa0cp-3, 0x1.d813519c7c16fp-3, -0x1.4dd8c86af58d6p-3, 0x1.e672b9b087ab8p-3, -0x1.768e331d95616p-3, 0x1.0198c29da7143p-2},
     {-0x1.6016da41e07ep-1, -0x1.83ef861a9d074p-5, -0x1.61f0129328756p-1, -0x1.f67c7526c0dap-5, -0x1.63c94ae4706ccp-1, -0x1.3484b21972566p-4, -0x1.677bbc06ffc45p-1, -0x1.a711b0a386bap-4}}},
    {"soak_18", 4, {{0x1.0acd581205a64p+29, -0x1.d4cf5910faac5p+28, 0x1.0b5703792ea9ep+29, -0x1.d11638f3bb185p+28, 0x1.0be0aee057ad8p+29, -0x1.cd5d18d67b845p+28, 0x1.0c25849a8a1bp+29, -0x1.cb80889a0c3b8p+28},
     {-0x1.71e8e40b9195ep-2, 0x1.4ec34251f3a15p-1, -0x1.07148f854485ep-2, 0x1.3fac45f73d6p-1, -0x1.38806e4b11a0ep-3, 0x1.309549115593ap-1, -0x1.9b5833898922p-4, 0x1.2909cae3fa73p-1}}},
    {"soak_19", 4, {{-0x1.7c2c245f13bbap-1, -0x1.8db29712587f8p-6, -0x1.7ccd284555b2ap-1, -0x1.7a487bbc91eacp-5, -0x1.7d6e2c2b97a99p-1, -0x1.16dbd5f7fbcafp-4, -0x1.7e0f3011d9a08p-1, -0x1.70936e11aea08p-4},
     {0x1.9886dbe18ac7ep-2, 0x1.90328823baea8p-5, 0x1.95bebe458998bp-2, 0x1.a5fbc9fef7a2p-5, 0x1.92f6a0a988698p-2, 0x1.bbc50bda34598p-5, 0x1.902e830d873a4p-2, 0x1.d18e4db57111p-5}}},
    {"soak_20", 4, {{-0x1.5d13fdc5bfa03p-3, 0x1.543d6c24d9c0ap-2, -0x1.5402b5cf697a9p-3, 0x1.60e43835d2828p-2, -0x1.4af16dd91354ep-3, 0x1.6d8b0446cb446p-2, -0x1.617a3d4159407p-3, 0x1.82c5eb1c498f7p-2},
     {-0x1.5621f1a958505p-1, 0x1.e78b0247ffb08p-3, -0x1.57bb63daaa634p-1, 0x1.02cb7655d221p-2, -0x1.5954d5a15c23dp-1, 0x1.11d1679e18005p-2, -0x1.5aee47680de46p-1, 0x1.20d758e65ddfap-2}}},
    {"soak_21", 5, {{-0x1.123c68e36c1c3p-2, 0x1.26a06e0288227p-2, -0x1.dad148932867ep-3, 0x1.f15edeae9041cp-3, -0x1.6edb8da4d87a3p-4, 0x1.0bbc41a8c9496p-4, -0x1.881541e8d90b8p-2, 0x1.b9a399d459ee5p-2, -0x1.33bfadb7198bbp-2, 0x1.506eef5bcf2e1p-2},
     {0x1.f09da753c298p-1, 0x1.759e5476aee1ep-1, 0x1.d84725961b26bp-1, 0x1.a0e36b422228ep-1, 0x1.5dcade3be7064p-1, 0x1.4b4f852477715p-1, 0x1.2687749a6452fp-1, 0x1.251acb2a6e6cbp-1, 0x1.9dfd9fb581e42p-1, 0x1.76d99f47e72bep-1}}},
    {"soak_22", 4, {{0x1.e4ca37ce67e78p-2, -0x1.2a22a58f3946fp-2, 0x1.996f33bb0f29fp-2, -0x1.3986d6d0c2688p-2, 0x1.bf1cb7ba602bbp-2, -0x1.31d4bdc987e96p-2, 0x1.c8533115d52ep-2, -0x1.2ff305d21ce97p-2},
     {0x1.21299f230858p-1, -0x1.f70613cb8032p-6, 0x1.34d51164990b8p-1, -0x1.b6b4a48b76558p-4, 0x1.2de837fd345acp-1, -0x1.1ce5aec88746p-4, 0x1.2c46e962b85dcp-1, -0x1.242f272851ccfp-4}}},
    {"soak_23", 4, {{0x1.b3f888d7da5p-2, -0x1.123512af82a9p-8, 0x1.96c7240d7c3cap-2, -0x1.0a2660814dbp-12, 0x1.7995bf431e294p-2, 0x1.e1e08d3eb1e6p-9, 0x1.5c645e6f27ebdp-2, 0x1.f282d0508cf38p-8},
     {0x1.28e8383365712p-2, -0x1.c2362bf0e1c9p-3, 0x1.2d14c91eabbb6p-2, -0x1.c011c23e7294ap-3, 0x1.31415a09f205ap-2, -0x1.bded588c03603p-3, 0x1.356deaf5384fep-2, -0x1.bbc8eed9942bcp-3}}},
    {"soak_24", 4, {{0x1.647760f6aebcfp+22, -0x1.3e6310fe0a9b8p+21, 0x1.6478bad1ce1dbp+22, -0x1.3e916a89c608p+21, 0x1.6476071b346d6p+22, -0x1.3e34b7661f7aep+21, 0x1.6476802805a2dp+22, -0x1.3e44f05b4b5fep+21},
     {-0x1.874b4b3e053ap-1, 0x1.b6ed83dee5f1dp-4, -0x1.84fcd3aa51529p-1, 0x1.be4bb1b36851ap-4, -0x1.899a361a02932p-1, 0x1.af97e602391cfp-4, -0x1.874b66bd4325ap-1, 0x1.b6efac14575ebp-4}}},
    {"soak_25", 4, {{-0x1.3d748ec74bbdcp-4, 0x1.651a6e6c65f9dp-1, -0x1.3df76f86dc7fcp-3, 0x1.70127788d71e4p-1, -0x1.07c39e0f19878p-4, 0x1.5633de65efdf9p-1, -0x1.57a2a2c48f905p-4, 0x1.614c430342e6dp-1},
     {0x1.e09ed8ae8f6dbp-2, 0x1.a37257023f635p-3, 0x1.e0e8eec27a85p-2, 0x1.8cf39fed26223p-3, 0x1.e01ae83e23852p-2, 0x1.cb81f5cd87e44p-3, 0x1.e05ce07659796p-2, 0x1.b77a2667e3a3cp-3}}},
    {"soak_26", 4, {{0x1.5278b1884382ap-3, -0x1.344363441e00ep-2, 0x1.5cfd42fc94627p-3, -0x1.3ccf643a29816p-2, 0x1.6781d470e5425p-3, -0x1.455b65303501ep-2, 0x1.720661b3f6c06p-3, -0x1.4de762be1f346p-2},
     {0x1.38d56f9f3f33fp-6, -0x1.348f1335f89c8p-6, 0x1.38c2eb57ff9e4p-6, -0x1.34daed1523787p-6, 0x1.38b06710c0089p-6, -0x1.3526c6f44e546p-6, 0x1.389de2c59dbf9p-6, -0x1.3572a0e363d64p-6}}},
    {"soak_27", 4, {{0x1.8096ea9d20f25p+5, -0x1.2488c8769b555p+6, 0x1.809f6010711e4p+5, -0x1.24837695ac9c3p+6, 0x1.8099bc6e66277p+5, -0x1.24870280dbb5p+6, 0x1.8098bfcb8dee7p+5, -0x1.2487a163ab938p+6},
     {-0x1.7deefd9c0edcap-1, -0x1.a762d1e9dbc39p-6, -0x1.8bec0faa74d35p-1, 0x1.696f72e97159ap-6, -0x1.9c15f360a6328p-1, 0x1.8c011ddd4626p-10, -0x1.8a9516a609ffep-1, -0x1.c9527af464dp-11}}},
    {"soak_28", 4, {{-0x1.843877945575p-6, 0x1.24dffbc80c3ddp-2, -0x1.3032292e8c35cp-5, 0x1.154db7f7f0b3ap-3, -0x1.30033df194e5dp-1, 0x1.a88b16410b852p-3, -0x1.0176a8b542e5p-5, 0x1.1061a7404d7bdp-3},
     {0x1.004728e5ccd9bp-1, 0x1.0a7fb9cce8fa8p-2, 0x1.e857d52c5f456p-2, 0x1.6262e48a9ea78p-3, 0x1.11ac4e3fad798p-1, 0x1.8ad1609a1fe0cp-2, 0x1.0b95b4603874cp-1, 0x1.5de7ffd24ca9cp-2}}},
    {"soak_29", 4, {{-0x1.0dbb8e14ee26cp-1, 0x1.006e871c2be98p-1, -0x1.26f97b1296302p-5, 0x1.0fde584d5aea8p-3, -0x1.b5a49f2e38346p-2, 0x1.c8638e8acfd79p-2, -0x1.c938b9ae741f8p-2, 0x1.cb92a857dc369p-2},
     {0x1.412a895922a3ap-1, 0x1.182d8646dfa77p-2, 0x1.4b378d9a4f84cp-3, -0x1.3ffd72220776ep-2, 0x1.60f2a08d77ffap-1, 0x1.683343b671ca8p-2, 0x1.510e94f34d51ap-1, 0x1.403064fea8b9p-2}}},
    {"soak_30", 4, {{-0x1.5693045801649p-3, -0x1.49389b8219aa8p-1, -0x1.8c72000ddf4d8p-4, -0x1.65201f8a4de1cp-1, -0x1.bd5d97931092cp-4, -0x1.6065aa9ef07f4p-1, -0x1.2c9cbd5957017p-3, -0x1.51552d98fe74fp-1},
     {-0x1.0a6291273dc88p-2, 0x1.e069754b06b16p-2, -0x1.8edf2b53b7a57p-3, 0x1.e890dd0934fc3p-2, -0x1.32d7dd2a3a121p-3, 0x1.b42a5deef9bc6p-2, -0x1.7d679587cc1c8p-3, 0x1.eb5d3618cffb2p-2}}},
    {"soak_31", 4, {{0x1.b4248f49dab7fp-3, 0x1.41a90873c09b4p-2, 0x1.c4703dcb8c47cp-3, 0x1.a7e5cb09d5f6ep-2, 0x1.a8dd203ec7b57p-3, 0x1.5f742b084bf74p-2, 0x1.b48cc17d26e75p-3, 0x1.66215cdc2f411p-2},
     {-0x1.b811b0cd53f3bp-2, -0x1.69bbcd621f75bp-2, -0x1.0cbb61832dc87p-1, -0x1.0ffd78031b2abp-2, -0x1.9df699af9cebep-2, -0x1.81c9dec3aebebp-2, -0x1.aeee9be953e42p-2, -0x1.7227204444cf4p-2}}},
    {"soak_32", 4, {{-0x1.1d4620aff93a1p-1, -0x1.4c0cc4bf7d2a9p-2, -0x1.18e71b50da2aep-1, -0x1.5ed86a45ca1cbp-2, -0x1.1486c7832827ap-1, -0x1.71a2dca904934p-2, -0x1.102673b576247p-1, -0x1.846d4f0c3f09cp-2},
     {0x1.1bc4668d9b678p-1, -0x1.f33dbd2f5dec1p-2, 0x1.1b6c7678543c9p-1, -0x1.e3196ee435de1p-2, 0x1.1b1486630d11ap-1, -0x1.d2f520990dd01p-2, 0x1.1abc9638005f8p-1, -0x1.c2d0ce4ed2dddp-2}}},
    {"soak_33", 4, {{-0x1.3cd361ce6fb8dp+19, 0x1.789ba759681dfp+19, -0x1.3ce361af6a082p+19, 0x1.789f1d4225677p+19, -0x1.3cb65c82ecad4p+19, 0x1.7895607237a75p+19, -0x1.3cc4df28ae33p+19, 0x1.789883e5cfe2ap+19},
     {-0x1.709340a76890cp-2, -0x1.cf6f5a57a2d7cp-2, -0x1.7b621c044e85ap-2, -0x1.c9ac810167d8p-2, -0x1.8863fe1944cacp-2, -0x1.cf1b4cf984d0ap-2, -0x1.783019f1fc441p-2, -0x1.cd7a1437da69fp-2}}},
    {"soak_34", 4, {{0x1.3a60b87ccac97p-3, 0x1.a489aea15a3a2p-5, 0x1.5b728dacbcf33p-3, 0x1.70947c8d2184ap-3, 0x1.57225079f9f59p-3, 0x1.4e37b2001836ap-3, 0x1.447147489b4c1p-3, 0x1.72a0888e1b12bp-4},
     {-0x1.1b4eb65f0a93fp-2, -0x1.695105d639ad2p-3, -0x1.0792fdfc4d377p-2, -0x1.f636283cfab5bp-3, -0x1.00ff163774e24p-2, -0x1.1296989199965p-2, -0x1.071e801c77298p-2, -0x1.f975e78bc38d6p-3}}},
    {"soak_35", 4, {{-0x1.92b58fae52e0ap-10, 0x1.05ee2b0e79ebbp-14, -0x1.9424c214bafd1p-10, 0x1.2e7dbf92370fcp-14, -0x1.94dc5b3b06461p-10, 0x1.42c5886709748p-14, -0x1.964c625fc0985p-10, 0x1.3e11eafd316ddp-14},
     {-0x1.b042a922c32f6p-5, -0x1.21fa9dda2581cp-7, -0x1.aedfc557ef6e2p-5, -0x1.31e09d0772678p-7, -0x1.ae2e538002d23p-5, -0x1.39d39c036599bp-7, -0x1.ad7ce1a816364p-5, -0x1.41c69aff58cbep-7}}},
    {"soak_36", 4, {{0x1.95e9378c0d068p-4, 0x1.ddca5ad85bf4fp-2, 0x1.20108624cbd9cp-6, 0x1.d4766de92e16dp-2, 0x1.dded59153ffdp-5, 0x1.d9206460c505ep-2, 0x1.426ff20b56828p-4, 0x1.db755f9c907d6p-2},
     {0x1.493ee07e3ecbep+25, -0x1.308d7582164e8p+27, 0x1.49a4f4e908131p+25, -0x1.307de31c475a1p+27, 0x1.496fdf72d8345p+25, -0x1.307f08563da3bp+27, 0x1.495d17e5c5066p+25, -0x1.30861f55ac35ap+27}}},
    {"soak_37", 4, {{-0x1.9a68c4f12caf7p-2, 0x1.ebcb2fb13aacap-2, -0x1.8c070e8549297p-2, 0x1.ebd1ecb2bd1fep-2, -0x1.7da554196613ep-2, 0x1.ebd8a9b61f5a3p-2, -0x1.6f3f27622b547p-2, 0x1.ebdf68ced5d33p-2},
     {0x1.9b8e52c547c71p-3, -0x1.0ed9c2364fa3ap-1, 0x1.b24417cbff7ebp-3, -0x1.12d87018504fp-1, 0x1.c8f9dcd2b7363p-3, -0x1.16d71dfa50fa8p-1, 0x1.edd410dd3e68ap-3, -0x1.15cf741e104acp-1}}},
    {"soak_38", 4, {{0x1.8189f1d78652cp+1, -0x1.d517a23be7d35p+3, 0x1.7f75ee50c7f6cp+1, -0x1.d5367a7e6ae31p+3, 0x1.7d61eaca099acp+1, -0x1.d55552c0edf2dp+3, 0x1.7939e33fdc076p+1, -0x1.d593034d2ec26p+3},
     {-0x1.8373cea41ada2p-18, 0x1.3372d97cc1ec8p-16, -0x1.7d4e66e94b172p-18, 0x1.3176cc8d2c0d4p-16, -0x1.7728fd93a51f1p-18, 0x1.2f7abf18ed9p-16, -0x1.6ade2e1e0599p-18, 0x1.2b82a539c1d19p-16}}},
    {"soak_39", 7, {{-0x1.f8fe9272a1955p-2, -0x1.91f4c280efa1bp-4, -0x1.f968e8833a703p-2, -0x1.bf8d032e58868p-4, -0x1.f9d33e93d34b1p-2, -0x1.ed2543dbc16b6p-4, -0x1.fa3d94a46c25fp-2, -0x1.0d5ec24495282p-3, -0x1.faa7eab50500dp-2, -0x1.242ae29b499a9p-3, -0x1.fb1240c59ddbbp-2, -0x1.3af702f1fe0dp-3, -0x1.fb7c96d636b69p-2, -0x1.51c32348b27f7p-3},
     {-0x1.09e7dcd24f8ecp-1, -0x1.2827f584d54d3p-2, -0x1.0c622d60a6feap-1, -0x1.2608cadfb97e4p-2, -0x1.0edbf998859f9p-1, -0x1.23e7252071b5dp-2, -0x1.1155c3fa1c7ep-1, -0x1.21c580f60947ap-2, -0x1.13cf8e5bb35c8p-1, -0x1.1fa3dccba0d98p-2, -0x1.164958bd4a3bp-1, -0x1.1d8238a1386b6p-2, -0x1.175406b35e3d4p-1, -0x1.227914fc95cb8p-2}}},
    {"soak_40", 4, {{0x1.a862c346ea6aap-3, 0x1.fa381b3686428p-3, 0x1.b770b836b2857p-3, 0x1.fb7b3b9a306b6p-3, 0x1.9b372fad6c04ep-3, 0x1.f91d6c83e65e9p-3, 0x1.a07a7d4bf11fdp-3, 0x1.f98e62b3ec3e2p-3},
     {0x1.256e5f7dd211ap-1, -0x1.050d8df0d81f2p-1, 0x1.159982333c0a1p-1, -0x1.1cc4adfcfc7f7p-1, 0x1.3be264e1bf298p-1, -0x1.fa514b501fc58p-2, 0x1.280e584c942a6p-1, -0x1.087f693390406p-1}}},
    {"soak_41", 4, {{-0x1.478f4681d68d3p-3, 0x1.ab70577db3b2ep-2, -0x1.708d535c481bbp-3, 0x1.a3669ae580576p-2, -0x1.5f24070d2ea89p-3, 0x1.8d33c537ea05p-2, -0x1.4dbabda9cea71p-3, 0x1.7700f343a3798p-2},
     {-0x1.c5dc87cac428dp-16, -0x1.169e60e4886f5p-15, -0x1.c5d442bcb4c88p-16, -0x1.169ca484341f6p-15, -0x1.c5cbfdaea5683p-16, -0x1.169ae823dfcf7p-15, -0x1.c5c3b8a09607fp-16, -0x1.16992bc38b7f8p-15}}},
    {"soak_42", 4, {{-0x1.4cf0d897d607ap-4, -0x1.56111a4c0bfa9p-2, -0x1.50ecd478d1134p-4, -0x1.4470391724613p-2, -0x1.48f4dcb6dafc1p-4, -0x1.67b1fb80f393fp-2, -0x1.4c5dae01df73ep-4, -0x1.589c3c0f26a59p-2},
     {-0x1.5f2c34eaaa84ep+24, -0x1.5549e016f287cp+25, -0x1.5f32fb4a9e5a4p+24, -0x1.5547ae67bb84p+25, -0x1.5f256e8ab6af8p+24, -0x1.554c11c6298b9p+25, -0x1.5f28d1bab09a3p+24, -0x1.554af8ee8e09ap+25}}},
    {"soak_43", 4, {{0x1.7830ab611f6b6p+28, -0x1.774631c864885p+27, 0x1.7832c78fa5055p+28, -0x1.7748b7e3e37b3p+27, 0x1.782c730599dc3p+28, -0x1.7741258e69e88p+27, 0x1.7830ab6175e38p+28, -0x1.774631c7435cep+27},
     {0x1.66f277ab73a9bp-1, -0x1.8c30afe92271cp-3, 0x1.5b6ead96a8d17p-1, -0x1.960e5d115801fp-3, 0x1.7dfa0bd5095a2p-1, -0x1.78755598b7517p-3, 0x1.6f01eb86ce744p-1, -0x1.8548b6b36359ap-3}}},
    {"soak_44", 4, {{-0x1.378a18ef17f72p-2, 0x1.13da7d39518bap-2, -0x1.218cb699b52c8p-2, 0x1.1e27306ea3565p-2, -0x1.25f2959e41a46p-2, 0x1.1c17da11b5d0bp-2, -0x1.3161de2c668d6p-2, 0x1.16bcc41ea7d7p-2},
     {0x1.1088d57ab0e19p-2, 0x1.f16e505a92e98p-3, 0x1.1be262fd58d61p-2, 0x1.27ae4c4e3b121p-2, 0x1.01cab0d7a039ap-2, 0x1.0fd563c305339p-2, 0x1.0e3adb1740f15p-2, 0x1.0b79cebdedec2p-2}}},
    {"soak_45", 4, {{0x1.b628e2c512509p-3, -0x1.17c3e8d76b2dap-1, 0x1.0dae2d3e3ebfap-2, -0x1.1bf72c2919f68p-1, 0x1.4047e919f457p-2, -0x1.202a6f7ac8bf6p-1, 0x1.72e1a4f5a9ee6p-2, -0x1.245db2cc77884p-1},
     {0x1.288b0ae863029p-2, 0x1.ba3112ef4789cp-2, 0x1.298a8a347afcep-2, 0x1.dd75e0151e564p-2, 0x1.2b0778cbfd976p-2, 0x1.005b19c9f93afp-1, 0x1.2a0d6e207c5dap-2, 0x1.11fb1bc4fc906p-1}}},
    {"soak_46", 4, {{-0x1.824883cbe31dcp-1, -0x1.dedb4c7a81b03p-2, -0x1.535fdac00db7cp-1, -0x1.0e0d0baf082acp-1, -0x1.6e2df1f74856cp-1, -0x1.f91ac850918b8p-2, -0x1.7b94fd92e5a64p-1, -0x1.e79b20c9d2268p-2},
     {0x1.138bafaa87fd8p-6, -0x1.af1f7123ddb3ep-2, -0x1.19826f6a6534p-7, -0x1.0a6ce2aedfa35p-1, 0x1.066c098f3506dp-4, -0x1.fd2a8f1347316p-2, 0x1.6660dd1d2c36cp-6, -0x1.df903f7fc867fp-2}}},
    {"soak_47", 6, {{0x1.00e6c1f0f1746p-2, 0x1.398636c365a2p-2, 0x1.00f9cc6dafa32p-2, 0x1.3995e25eb4303p-2, 0x1.010cd6e057947p-2, 0x1.39a58dfbc663ap-2, 0x1.009a9813e8d9ap-2, 0x1.3947885cba5c6p-2, 0x1.00ada28ee3631p-2, 0x1.395733edf2ad1p-2, 0x1.00b38c427f72ap-2, 0x1.395c11b911031p-2},
     {-0x1.8087425ada361p-2, -0x1.2a89328ed2ea1p-3, -0x1.8b76a54cca30bp-2, -0x1.4b36e6fe878fbp-3, -0x1.9666060530fe6p-2, -0x1.6be494c83b06fp-3, -0x1.54c9bb062ca56p-2, -0x1.4fa4dc380560ap-4, -0x1.5fb91df81cap-2, -0x1.910045176eabcp-4, -0x1.6b347781122e2p-2, -0x1.d5a036b3352d1p-4}}},
    {"soak_48", 4, {{-0x1.0fc1614a65dfap-2, -0x1.958df36bcb498p-1, -0x1.b3c81711dd546p-3, -0x1.8bb8116ee727ep-1, -0x1.7deac51244022p-3, -0x1.86cd20c8462a2p-1, -0x1.480d7312aabp-3, -0x1.81e23021a52c6p-1},
     {-0x1.4fd3dcbaae55cp-3, -0x1.788ceef255955p-2, -0x1.073413681aa9ap-3, -0x1.7d40fd3e4531dp-2, -0x1.c5c8656caa458p-4, -0x1.7f9b042278784p-2, -0x1.7d28a4091f37cp-4, -0x1.81f50b06abbebp-2}}},
    {"soak_49", 4, {{0x1.dfe46c2995d5ep-2, 0x1.4e6e9ed18dc64p-3, 0x1.e9140fa6ad2dp-2, 0x1.c2992259a7dacp-4, 0x1.ec0971b4ae257p-2, 0x1.0f625a7ef42e6p-3, 0x1.e6722dc9024f8p-2, 0x1.10b60ea4bf51dp-3},
     {-0x1.802bc221801ccp-1, -0x1.e15aa119b754ap-3, -0x1.8360e348a4f05p-1, -0x1.402e7c3a55302p-2, -0x1.822778119b665p-1, -0x1.21d5d63657854p-2, -0x1.81299d198dc18p-1, -0x1.094193619997cp-2}}},
    {"soak_50", 4, {{-0x1.3a7094d0065a9p-1, -0x1.aa4386c331e09p-2, -0x1.3354747cdec3ep-1, -0x1.b8905d8d6497bp-2, -0x1.2ad41033bd6f1p-1, -0x1.ad0ff870a53fap-2, -0x1.2253abeca6c2ap-1, -0x1.a18f98fc0c07fp-2},
     {-0x1.c6da3041cd246p-3, -0x1.0eb3e043a1199p-1, -0x1.a30719dc6e901p-3, -0x1.0ef71f49ba676p-1, -0x1.7f3403770ffbcp-3, -0x1.0f3a5e4fd3b53p-1, -0x1.5b60e51292c32p-3, -0x1.0f7d9d64efa79p-1}}},
    {"soak_51", 4, {{0x1.048f28beb5582p-1, -0x1.66878c66953b6p-4, 0x1.edec646b2b084p-2, -0x1.43a8582b5d31p-4, 0x1.d2ba7758eb604p-2, -0x1.20c923f02526ap-4, 0x1.8124b0222c685p-2, -0x1.70570e7cfa0f4p-5},
     {0x1.fa39242b888fcp+7, 0x1.cd5ad848bdcd3p+8, 0x1.fa37fc742447fp+7, 0x1.cd5834d0115e9p+8, 0x1.fa36d4bc5284ap+7, 0x1.cd5591566adbcp+8, 0x1.fa335d95b831cp+7, 0x1.cd4da6eb6b7bbp+8}}},
    {"soak_52", 4, {{0x1.923c48e9ac6aap-1, 0x1.7a1ae01717c6ep-2, 0x1.021249b7933d5p-1, 0x1.19d4e23fcb513p-1, 0x1.82774ab532ca9p-1, 0x1.339626290a52ap-2, 0x1.82be1f3147fe4p-1, 0x1.660509a0ccc7fp-2},
     {0x1.33b0bc16ef74fp+13, -0x1.c57dd6e7d87e7p+15, 0x1.3a6344fe8ce2ep+13, -0x1.c6269eee1f96ep+15, 0x1.3259d3e2cc079p+13, -0x1.c55c154c6aebcp+15, 0x1.3324c14046f9p+13, -0x1.c5700f4561bd3p+15}}},
    {"soak_53", 4, {{0x1.4d8b03a91efdap-4, -0x1.80fe9b3a10724p-1, 0x1.447afcd56c168p-4, -0x1.7a80281ccb74bp-1, 0x1.3b6af601b92f8p-4, -0x1.7401b4ff86773p-1, 0x1.9aecb4285143ap-5, -0x1.76677fd3e4f11p-1},
     {0x1.13f2ff51a29bep-25, 0x1.1d500cb1aca44p-22, 0x1.0687b11ea15a8p-25, 0x1.1d076f2e36042p-22, 0x1.f238c5d740325p-26, 0x1.1cbed1aabf63fp-22, 0x1.bc8b8d0b3b2cfp-26, 0x1.1c2d96a3d223ap-22}}},
    {"soak_54", 4, {{-0x1.1cb883135f419p-1, 0x1.e30685d63557bp-3, -0x1.2122ee0ed8d54p-1, 0x1.d5b902a574fddp-3, -0x1.0b0ed72578f2cp-1, 0x1.0c1e494c9b5fbp-2, -0x1.11ae779eaf505p-1, 0x1.022426e80b1c4p-2},
     {0x1.af553851e7c3ap+1, -0x1.8feda31c16d94p+5, 0x1.a5bc69687ee82p+1, -0x1.8fb3a8b85dc02p+5, 0x1.d5b86a9873d9cp+1, -0x1.90d58ce2cfd51p+5, 0x1.b8ee067a14c3dp+1, -0x1.90279d9fcc203p+5}}},
    {"soak_55", 4, {{-0x1.c485fadf1beep-3, -0x1.6d1bc5688132p-9, -0x1.1e429b8493eccp-2, -0x1.72160ba067b08p-3, -0x1.b91855794babdp-3, 0x1.cff8b0fca5548p-7, -0x1.c08600fb79707p-3, 0x1.9c3d5110f9e28p-9},
     {-0x1.77b47d7a7fcf8p-1, 0x1.7444c579c7b84p-2, -0x1.8ff4165a951d6p-1, 0x1.a2ed02306e4e6p-3, -0x1.73021465b789ep-1, 0x1.60131d06faa0ap-2, -0x1.77dd118d4b7f6p-1, 0x1.5dd1eae359127p-2}}},
    {"soak_56", 4, {{-0x1.59dea75e01fb1p-3, 0x1.9dc8d0e7dc71cp-7, -0x1.4eaab85e17249p-3, 0x1.cb84247b1d1dbp-7, -0x1.532044f13e424p-3, 0x1.3deda9e7c8b2ap-6, -0x1.5779d03a0849ep-3, 0x1.96728e7741192p-6},
     {-0x1.01d58358b5447p+25, -0x1.3814719fc921p+22, -0x1.017aa8596917ap+25, -0x1.311bb07a203a2p+22, -0x1.011fcd5a1ceadp+25, -0x1.2a22ef5477534p+22, -0x1.00c4f25ad0bep+25, -0x1.232a2e2ece6c5p+22}}},
    {"soak_57", 4, {{-0x1.89c42930f43bp-2, -0x1.f6347e5ae3ec1p-2, -0x1.1f1aa4deb1f4p-2, -0x1.83fdbd13bd28ap-3, -0x1.99c3fdc24828ap-2, -0x1.1237df673c964p-1, -0x1.946eb6af5b94ap-2, -0x1.0a835458aa4f6p-1},
     {-0x1.9e09142975ad8p-4, -0x1.54f5d8ccd70e2p-1, -0x1.5c5169247b7c2p-5, -0x1.f3d8068c15d61p-2, -0x1.9caae873e30bap-4, -0x1.2b79f21a3eb58p-1, -0x1.8abcc829d7322p-4, -0x1.471fefa35b03p-1}}},
    {"soak_58", 4, {{0x1.bfffcbcb6ac73p-2, -0x1.4f3f3601a0b55p-1, 0x1.da885179036cap-2, -0x1.53ea9c4162a92p-1, 0x1.a577461dd221ep-2, -0x1.4a93cfc1dec18p-1, 0x1.b6b669cea88d5p-2, -0x1.4d9cd2381cd33p-1},
     {0x1.2e5b99558bfcp-3, 0x1.283d46379df26p-2, 0x1.022c3dc25ba2dp-3, 0x1.0c5c36545e32cp-2, 0x1.5a8af9e0b23a6p-3, 0x1.441e593d6d765p-2, 0x1.2d5fbda7b0d71p-3, 0x1.279e5c5ecc24ep-2}}},
    {"soak_59", 4, {{0x1.51c84a5762c4fp-3, 0x1.2bc53047e4bacp-1, 0x1.4005c155c5bd9p-3, 0x1.21113be3137a1p-1, 0x1.2e4335436ad3ap-3, 0x1.165d45a5562d4p-1, 0x1.1c80a9310fe9bp-3, 0x1.0ba94f6798e06p-1},
     {-0x1.737aab739d1eap-4, -0x1.298df37af1e4fp-1, -0x1.348ae6d7a1d86p-4, -0x1.29d513bbfc739p-1, -0x1.eb36247c67beep-5, -0x1.2a1c340f191a1p-1, -0x1.6d567b498bcd2p-5, -0x1.2a63546235c09p-1}}},
    {"soak_after_0", 6, {{0x1.00e6c1f0f1746p-2, 0x1.398636c365a2p-2, 0x1.00f9cc6dafa32p-2, 0x1.3995e25eb4303p-2, 0x1.010cd6e057947p-2, 0x1.39a58dfbc663ap-2, 0x1.009a9813e8d9ap-2, 0x1.3947885cba5c6p-2, 0x1.00ada28ee3631p-2, 0x1.395733edf2ad1p-2, 0x1.00b38c427f72ap-2, 0x1.395c11b911031p-2},
     {-0x1.8087425ada361p-2, -0x1.2a89328ed2ea1p-3, -0x1.8b76a54cca30bp-2, -0x1.4b36e6fe878fbp-3, -0x1.9666060530fe6p-2, -0x1.6be494c83b06fp-3, -0x1.54c9bb062ca56p-2, -0x1.4fa4dc380560ap-4, -0x1.5fb91df81cap-2, -0x1.910045176eabcp-4, -0x1.6b347781122e2p-2, -0x1.d5a036b3352d1p-4}}},
    {"soak_after_1", 7, {{-0x1.cb70f1f7ca9eep-2, -0x1.ac057d941b1ccp-3, -0x1.027e163eadcecp-1, -0x1.3d1c5ad966638p-6, -0x1.5d22f64e752a9p-1, -0x1.f220d2bf7801p-3, -0x1.5d57072862c44p-1, -0x1.f3282dcff567dp-3, -0x1.38e4784a8f694p-1, -0x1.3acd007ee7164p-3, -0x1.027e70c5b970cp-1, -0x1.3d2aaa0c911ep-6, -0x1.e836e9c19ec03p-2, -0x1.d3aad2d5ad408p-4},
     {0x1.9e9dbe5721245p-2, 0x1.b456e4dd1a244p-2, 0x1.d3d58b70ac2a5p-2, 0x1.aae0ef25a3934p-2, 0x1.93c179fa2f7e4p-2, 0x1.eb142d5be54cep-2, 0x1.6e97f0960ef3p-2, 0x1.595ff2681048fp-1, 0x1.b0feb331bc492p-2, 0x1.6a800fde7e98bp-1, 0x1.888e401d0ba04p-2, 0x1.71082ff105c39p-1, 0x1.6675ac15b8bc8p-2, 0x1.67a3f84f589ccp-1}}},
    {"soak_after_2", 6, {{0x1.b73bddb3a88dcp-3, -0x1.e69f716c17689p-2, 0x1.725700662f438p-2, -0x1.021b3fac423dp-1, 0x1.85d510a0dc438p-2, -0x1.320834751368ap-1, 0x1.89a3666d34ea2p-2, -0x1.0464b779060f3p-1, 0x1.3e7f17b56ec34p-4, -0x1.cb23aa07d686ap-2, 0x1.553d27748757ep-3, -0x1.dd00eba29a4cbp-2},
     {-0x1.9e83e0637f1e9p-9, -0x1.c7d7d94944bf8p-8, -0x1.a00b31f8cae88p-9, -0x1.c73d72f1fd37cp-8, -0x1.a0d062961bbf6p-9, -0x1.c73f84b11eed4p-8, -0x1.a4c650309f0afp-9, -0x1.c5dbf3073dedep-8, -0x1.a4a0e4be828ep-9, -0x1.c5fe94c36b2bcp-8, -0x1.9fecce8968a9ep-9, -0x1.c78ba5181c871p-8}}},
    {"soak_after_3", 6, {{0x1.0b33b59a35aadp-2, -0x1.b845cc9cfe7p-11, 0x1.4c2e9a63ef7ecp-3, -0x1.907fc52f9a648p-6, 0x1.f3aadff0efe6dp-3, -0x1.1bc3a6a1b8516p-7, 0x1.d48942850e1fp-2, 0x1.595dcb1ef2536p-4, 0x1.33589111cc9dap-2, 0x1.8e16d26324b88p-6, 0x1.4ed8eeb14a53ep-2, 0x1.ed49a96c19e21p-6},
     {0x1.1701e7990d4fep-1, 0x1.ec14c4fb5b46fp-2, 0x1.031c23bd6d164p-1, 0x1.86155e05f3a53p-2, 0x1.d7e9c5baff979p-2, 0x1.0f65610afb6dap-2, 0x1.a99b43fb2502ap-2, 0x1.316ac820066cp-3, 0x1.1f79920e593e6p-1, 0x1.0bbe464816868p-1, 0x1.19f896754e49cp-1, 0x1.fb45e46f717f7p-2}}},
    {"soak_after_4", 8, {{-0x1.009101c715666p-2, -0x1.73e14cfa8cd3ap-2, -0x1.29774031e6ed3p-1, -0x1.a664376be5acbp-3, -0x1.049d63127cc7cp-2, -0x1.800760e9e2a8cp-2, -0x1.0401e585f1d71p-3, -0x1.181e5d89270aap-4, -0x1.05e9fef99df18p-2, 0x1.c77c5b43ce5ap-4, -0x1.d0b609133f2c4p-2, 0x1.25fad65624254p-5, -0x1.00b1fec4d1492p-2, 0x1.a3f1507e2a0ep-4, -0x1.6b6368e6b4b54p-3, -0x1.34ca0d80fc59p-4},
     {-0x1.3ceada32a3011p-2, -0x1.f2f7b4e914c54p-2, -0x1.a815fac449051p-2, -0x1.2073163b99d18p-1, -0x1.93c7c790e2adbp-4, -0x1.1d9ad36f62871p-1, -0x1.fae9facf73837p-4, -0x1.06e87ecb4c33bp-3, -0x1.b5239e9e1622ep-4, -0x1.1dad9efc36531p-1, -0x1.2de58402e7f83p-2, -0x1.1f5fb596517ccp-1, -0x1.5de465df89833p-2, -0x1.4938c8d5cefc1p-2, -0x1.4d67a00916422p-2, -0x1.9e183edf71e0ap-2}}},
    {"soak_after_5", 4, {{-0x1.0ae2b98412d1fp-1, -0x1.c980b1f720e9fp-5, -0x1.124a7a47e5e9ap-1, -0x1.7a34b27e938d2p-4, -0x1.0ae2b98412d1fp-1, -0x1.c980b1f720eap-5, -0x1.71eade0388361p-2, 0x1.25e2f5db2342p-16},
     {0x1.33533fe9ddca4p-4, -0x1.7140a51474fdep-2, 0x1.745ca7769c72dp-2, -0x1.05a56ee9416bdp-1, 0x1.9e45d32f4e8c7p-2, -0x1.07c4a9bb6d4a2p-1, 0x1.355131925ee08p-2, -0x1.ea2d9fdd60ae9p-2}}},
    {"soak_after_6", 6, {{0x1.124679d9252e7p-7, -0x1.2d913d42f44aap-1, -0x1.b47d3e2d8a8p-8, -0x1.f8e19593e94c3p-2, 0x1.7536a3d47993p-7, -0x1.42d0b0ede1e5cp-1, 0x1.d8b3d280bdc75p-2, -0x1.57df09270a018p-1, 0x1.c119eb82783cbp-2, -0x1.4e8bb1afaaa61p-1, 0x1.e6431cd038f83p-3, -0x1.4cc1c4a90e783p-1},
     {0x1.bfe563ca71a56p-2, 0x1.2996f1d75262p-1, 0x1.69803eab498cep-2, 0x1.292dc91f37faep-1, 0x1.973ca241754acp-2, 0x1.e609435114caep-3, 0x1.9019502628479p-2, 0x1.29d9f7d8083aap-2, 0x1.733fe1acfb2b8p-2, 0x1.03bc242c6ddecp-1, 0x1.9992a2bbb6687p-2, 0x1.16a98b01e0206p-1}}},
    {"offset_1e15", 4, {{0x1.c6bf5263401b9p+49, 0x1.c6bf52634002cp+49, 0x1.c6bf52634009dp+49, 0x1.c6bf526340042p+49, 0x1.c6bf52634004fp+49, 0x1.c6bf526340247p+49, 0x1.c6bf52634009ep+49, 0x1.c6bf526340021p+49},
     {0x1.c6bf52634011cp+49, 0x1.c6bf5263401ecp+49, 0x1.c6bf52633fffep+49, 0x1.c6bf526340247p+49, 0x1.c6bf5263400cdp+49, 0x1.c6bf526340205p+49, 0x1.c6bf5263400f4p+49, 0x1.c6bf5263401f8p+49}}},
};

/* Several Steiner vertices crowded into a sliver thinner than the spacing
 * of doubles (the repair moves one vertex at a time, and neither one nor
 * two fan vertices fit), or a quadrilateral whose kernel holds no double
 * (soak_after_5: area 2e-35, a unit in the last place squared is 1e-32):
 * not solved yet. The soak_after_* pieces are the ones a 20,000-pair soak
 * still met after the repair; soak_47 and soak_after_0 (the same piece)
 * now take the two-vertex fan. */
static const char *const open_cases[] = {"soak_after_1", "soak_after_2", "soak_after_3",
                                          "soak_after_4", "soak_after_5", "soak_after_6"};

static int is_open(const char *name)
{
    for (size_t i = 0; i < sizeof open_cases / sizeof *open_cases; i++)
        if (strcmp(open_cases[i], name) == 0) return 1;
    return 0;
}

static void run(const sliver_case *c, cm_method method)
{
    const double *polys[2] = {c->xy[0], c->xy[1]};
    size_t counts[2] = {c->n, c->n};
    cm_options o;
    cm_options_init(&o);
    o.method = method;
    o.remesh = 0;
    cm_result *r = NULL;
    cm_status s = cm_triangulate_polygons(polys, counts, 2, &o, &r);
    char why[256] = "";
    int ok = s == CM_OK && rc_check(r, polys, 2, c->n, why, sizeof why);
    if (!ok && is_open(c->name) && s == CM_ERR_PRECISION &&
        strstr(cm_result_message(r), "stay inverted: no double position")) {
        printf("%s (%s): still open, fails cleanly\n", c->name,
               method == CM_METHOD_OVERLAY ? "overlay" : "partition");
        ok = 1;
    } else if (!ok)
        fprintf(stderr, "%s (%s): %s %s %s\n", c->name, method == CM_METHOD_OVERLAY ? "overlay" : "partition",
                cm_status_string(s), r ? cm_result_message(r) : "", why);
    CHECK(ok);
    cm_result_free(r);
}

/* A pair with no valid answer in doubles, which must fail cleanly:
 * geometry 0 is the dart (0,0) (1,1) (1,0) (2,3) (vertex 1 reflex) shifted
 * by 2^52, where the doubles are exactly the integers; geometry 1 is the
 * same dart with its vertices renumbered so that vertex 0 is reflex.
 * - A Steiner vertex of a valid result lies strictly inside the polygon in
 *   every geometry (it is an interior vertex of a disk of positive
 *   triangles whose boundary is the polygon, covered exactly once).
 * - The open dart holds no integer point, so no double: a valid result
 *   has no Steiner vertex.
 * - Without Steiner vertices two quadrilaterals share one diagonal, but
 *   geometry 0 admits only 1-3 and geometry 1 only 0-2.
 * The construction ends with CM_ERR_PRECISION, naming the polygon. */
static void no_double_answer(void)
{
    const double big = 0x1p52;
    const double a[8] = {big, big, big + 1, big + 1, big + 1, big, big + 2, big + 3};
    const double b[8] = {1, 1, 1, 0, 2, 3, 0, 0};
    const double *polys[2] = {a, b};
    size_t counts[2] = {4, 4};
    cm_result *r = NULL;
    cm_status s = cm_triangulate_polygons(polys, counts, 2, NULL, &r);
    long polygon = -1, vertex = -1, other = -1;
    cm_result_error_location(r, &polygon, &vertex, &other);
    CHECK_MSG(s == CM_ERR_PRECISION && strstr(cm_result_message(r), "no double position") && polygon >= 0,
              "%s: %s",
              cm_status_string(s), cm_result_message(r));
    cm_result_free(r);
}

int main(void)
{
    no_double_answer();
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        run(&cases[i], CM_METHOD_OVERLAY);
        run(&cases[i], CM_METHOD_PARTITION);
    }
    return check_summary("overlay_slivers");
}
