"""Boundary splits in the remesher (arclength and auto): where the
correspondence puts a long piece of the common boundary beside a crowded
stretch, the remesher halves boundary edges, each new point at the middle
parameter of its piece's input edge in every polygon. The fixture: the
glyphs "3" and "C" of FreeSerif Italic, 48 vertices each, resampled by
arc length from the bottom-left point (`cm_gen_pairs --set hard`,
tune_FreeSerifItalic_3_C_n48). In auto mode its worst triangles sit where
the conformal correspondence crowds 20 pieces into 3 % of one edge of the
"3": with the boundary fixed the remesher ended at 5.2 degrees (the
certified ceiling is 14.4); with boundary splits it reaches above 12."""
import numpy as np
import pytest

import compatmesh

GLYPH_3 = np.array([
    (0.02240574359893799, 0.02555835247039795), (0.07153165340423584, -0.0020456910133361816), (0.1289852261543274, -0.006987094879150391),
    (0.18650132417678833, -0.0022426843643188477), (0.24217379093170166, 0.012829124927520752), (0.29325252771377563, 0.039556026458740234),
    (0.33695822954177856, 0.0771600604057312), (0.371911883354187, 0.1230211853981018), (0.3953896760940552, 0.17565250396728516),
    (0.4054882526397705, 0.23240166902542114), (0.40187597274780273, 0.2898820638656616), (0.3793584704399109, 0.34267449378967285),
    (0.33800530433654785, 0.3825192451477051), (0.3311319351196289, 0.4094066619873047), (0.38358139991760254, 0.4335842728614807),
    (0.43149369955062866, 0.46558260917663574), (0.4614752531051636, 0.5140548944473267), (0.46420419216156006, 0.5713297724723816),
    (0.44129258394241333, 0.6236868500709534), (0.39696675539016724, 0.6600557565689087), (0.3416405916213989, 0.6753559112548828),
    (0.28425806760787964, 0.6711732745170593), (0.231276273727417, 0.6487894058227539), (0.18794840574264526, 0.6109061241149902),
    (0.1724165678024292, 0.5687448382377625), (0.21361345052719116, 0.6046236753463745), (0.2644939422607422, 0.6309483647346497),
    (0.3215438723564148, 0.6293107271194458), (0.3658134937286377, 0.5940617918968201), (0.3789239525794983, 0.5386576652526855),
    (0.363280713558197, 0.4836764931678772), (0.3242563009262085, 0.441608726978302), (0.2740231156349182, 0.4133261442184448),
    (0.21953535079956055, 0.39424699544906616), (0.16328924894332886, 0.3811227083206177), (0.15811794996261597, 0.360628604888916),
    (0.2153434157371521, 0.35331958532333374), (0.26878273487091064, 0.33205926418304443), (0.3074533939361572, 0.2901715040206909),
    (0.323535680770874, 0.2349715232849121), (0.3253878951072693, 0.17731547355651855), (0.31348633766174316, 0.1209980845451355),
    (0.283507764339447, 0.07200217247009277), (0.2369261384010315, 0.03871995210647583), (0.1802746057510376, 0.032952845096588135),
    (0.1289955973625183, 0.05890375375747681), (0.07885688543319702, 0.08721047639846802), (0.02435356378555298, 0.07963091135025024),
])
GLYPH_C = np.array([
    (0.10638481378555298, 0.06514978408813477), (0.15737968683242798, 0.021614789962768555), (0.2183687686920166, -0.0062056779861450195),
    (0.2845197916030884, -0.01745295524597168), (0.35158759355545044, -0.014461040496826172), (0.4162810444831848, 0.003333568572998047),
    (0.4750633239746094, 0.03572171926498413), (0.5270000100135803, 0.07835644483566284), (0.5734751224517822, 0.1269332766532898),
    (0.5308392643928528, 0.11784297227859497), (0.47837620973587036, 0.07582062482833862), (0.4196881651878357, 0.04329472780227661),
    (0.35440999269485474, 0.02808469533920288), (0.28744959831237793, 0.03103846311569214), (0.22619634866714478, 0.057477474212646484),
    (0.1824272871017456, 0.10785812139511108), (0.16031837463378906, 0.17106789350509644), (0.1550421118736267, 0.23800170421600342),
    (0.16065484285354614, 0.3049648404121399), (0.1757022738456726, 0.3704579472541809), (0.1996867060661316, 0.4332311153411865),
    (0.23228108882904053, 0.49199122190475464), (0.2735089063644409, 0.5450356006622314), (0.32395172119140625, 0.5892826318740845),
    (0.3841245174407959, 0.618799090385437), (0.4502354860305786, 0.6298767924308777), (0.5164985656738281, 0.6208885908126831),
    (0.571002185344696, 0.5829598307609558), (0.6009767651557922, 0.5232707262039185), (0.6218488812446594, 0.466191828250885),
    (0.6399688124656677, 0.5239945650100708), (0.6522629261016846, 0.5901167392730713), (0.6645569801330566, 0.6562389135360718),
    (0.6151434779167175, 0.6425887942314148), (0.5489003658294678, 0.6525300741195679), (0.48266738653182983, 0.6640152335166931),
    (0.41553473472595215, 0.6644476056098938), (0.34955912828445435, 0.651918351650238), (0.286967933177948, 0.6275497674942017),
    (0.22924262285232544, 0.5931755900382996), (0.1774156093597412, 0.5504131317138672), (0.13265490531921387, 0.5003015398979187),
    (0.09572643041610718, 0.44416284561157227), (0.06775504350662231, 0.3830733895301819), (0.04992973804473877, 0.3183034658432007),
    (0.043090105056762695, 0.25147414207458496), (0.04822063446044922, 0.18453669548034668), (0.06897211074829102, 0.12077188491821289),
])


def check_on_input_edges(inputs, result):
    """Every input keeps all its vertices bit-identical and in (cyclic)
    order, either way round (a clockwise input runs backwards); every other
    boundary point is P[e] + t (P[e+1] - P[e]) bit for bit."""
    n = result.stats["n"]
    for points, vertices, source in zip(inputs, result.vertices, result.boundary_source):
        m, own = len(points), source["t"] == 0
        order = list(source["edge"][own])
        assert order in ([(order[0] + i) % m for i in range(m)], [(order[0] - i) % m for i in range(m)])
        assert np.array_equal(vertices[:n][own], points[source["edge"][own]])
        for i in np.flatnonzero(~own):
            e, t = source["edge"][i], source["t"][i]
            a, b = points[e], points[(e + 1) % m]
            assert 0 < t < 1
            assert tuple(vertices[i]) == (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])), i


def test_auto_splits_boundary_edges_where_the_boundary_binds():
    inputs = (GLYPH_3, GLYPH_C)
    r = compatmesh.triangulate(inputs, correspondence="auto")
    before = compatmesh.triangulate(inputs, correspondence="auto", remesh=False)
    assert r.stats["n"] > before.stats["n"]  # points the remesher added on the boundary
    check_on_input_edges(inputs, r)
    assert min(q["min_angle_deg"] for q in r.stats["quality"]) >= 12.0


def test_morph_ends_at_the_inputs_with_the_added_points():
    """The morph's end sections are the two meshes, added boundary points
    included, and no section has an inverted triangle."""
    inputs = (GLYPH_3, GLYPH_C)
    r = compatmesh.triangulate(inputs, correspondence="auto")
    m = compatmesh.morph(inputs, frames=5, correspondence="auto")
    n = r.stats["n"]
    assert np.array_equal(m["sections"][0][:n], r.vertices[0][:n])
    assert np.array_equal(m["sections"][-1][:n], r.vertices[1][:n])
    assert not m["inverted"].any()


@pytest.mark.parametrize("mode", ["auto", "arclength"])
def test_clockwise_inputs_keep_the_contract(mode):
    """A clockwise input's pieces run down its input edges: the points the
    remesher adds there still come back from [e, t]."""
    for inputs in ((GLYPH_3, GLYPH_C[::-1]), (GLYPH_3[::-1], GLYPH_C[::-1])):
        check_on_input_edges(inputs, compatmesh.triangulate(inputs, correspondence=mode))


def test_index_never_splits_a_boundary_edge():
    r = compatmesh.triangulate((GLYPH_3, GLYPH_C), correspondence="index")
    assert r.stats["n"] == 48
    for source in r.boundary_source:
        assert list(source["edge"]) == list(range(48)) and not source["t"].any()
