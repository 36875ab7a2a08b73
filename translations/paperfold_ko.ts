<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ko">
<context>
    <name>Legend</name>
    <message>
        <source>simulation mesh (edges)</source>
        <translation>시뮬레이션 메시 (모서리)</translation>
    </message>
    <message>
        <source>Break probability P (Eq. 10, per %1 % more contraction)</source>
        <translation>파단 확률 P (식 10, 수축이 %1 % 늘 때마다)</translation>
    </message>
    <message>
        <source>breakable spring</source>
        <translation>파단 가능한 스프링</translation>
    </message>
    <message>
        <source>unbreakable spring</source>
        <translation>파단되지 않는 스프링</translation>
    </message>
    <message>
        <source>crease (broken)</source>
        <translation>주름 (파단됨)</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>힌지</translation>
    </message>
    <message>
        <source>broken in the last second</source>
        <translation>최근 1초 안에 파단</translation>
    </message>
    <message>
        <source>Strain |l/l0 - 1|, stretched or compressed</source>
        <translation>변형률 |l/l0 - 1| (늘어남 또는 줄어듦)</translation>
    </message>
</context>
<context>
    <name>UndoCommands</name>
    <message numerus="yes">
        <source>Push (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>누르기 (파단 또는 힌지 %n개)</numerusform>
        </translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 변경</translation>
    </message>
    <message>
        <source>stretch stiffness</source>
        <translation>인장 강성</translation>
    </message>
    <message>
        <source>bending stiffness</source>
        <translation>굽힘 강성</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>적분기</translation>
    </message>
    <message>
        <source>paper</source>
        <translation>종이</translation>
    </message>
    <message>
        <source>Jacobi sweeps</source>
        <translation>야코비 반복 횟수</translation>
    </message>
    <message>
        <source>steps per second</source>
        <translation>초당 단계 수</translation>
    </message>
    <message>
        <source>gravity outside the filter</source>
        <translation>필터 밖의 중력</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>접기</translation>
    </message>
    <message>
        <source>Settle</source>
        <translation>안정</translation>
    </message>
    <message numerus="yes">
        <source>Grab (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>잡기 (파단 또는 힌지 %n개)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pin %n vertex(es)</source>
        <translation>
            <numerusform>고정 (정점 %n개)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Unpin %n vertex(es)</source>
        <translation>
            <numerusform>고정 해제 (정점 %n개)</numerusform>
        </translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>초기화</translation>
    </message>
    <message numerus="yes">
        <source>Fold (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>접기 (파단 또는 힌지 %n개)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pf::ActionTexts</name>
    <message>
        <source>&amp;Press (sphere on a sheet)</source>
        <translation>누르기 (시트 위의 구)(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Drape (hanging sheet)</source>
        <translation>늘어뜨리기 (매달린 시트)(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Compress (edges pushed together)</source>
        <translation>압축 (양 끝을 밀기)(&amp;C)</translation>
    </message>
    <message>
        <source>D&amp;rop (tilted sheet falls)</source>
        <translation>떨어뜨리기 (기울어진 시트가 떨어짐)(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>열기(&amp;O)…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>저장(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>다른 이름으로 저장(&amp;A)…</translation>
    </message>
    <message>
        <source>Save &amp;Recording…</source>
        <translation>기록 저장(&amp;R)…</translation>
    </message>
    <message>
        <source>Save everything done since New or Open; paperfold replay does it again</source>
        <translation>새로 만들기 또는 열기 이후의 모든 작업을 저장합니다. paperfold replay로 다시 실행할 수 있습니다</translation>
    </message>
    <message>
        <source>Export &amp;Image…</source>
        <translation>이미지 내보내기(&amp;I)…</translation>
    </message>
    <message>
        <source>Export &amp;Mesh…</source>
        <translation>메시 내보내기(&amp;M)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>끝내기(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>재생(&amp;P)</translation>
    </message>
    <message>
        <source>Play or pause the simulation (Space)</source>
        <translation>시뮬레이션 재생 또는 일시 정지 (Space)</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>한 단계(&amp;T)</translation>
    </message>
    <message>
        <source>Advance one step</source>
        <translation>한 단계 진행</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>초기화(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Spring kinds</source>
        <translation>스프링 종류(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Break probability</source>
        <translation>파단 확률(&amp;B)</translation>
    </message>
    <message>
        <source>S&amp;train</source>
        <translation>변형률(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Recent breaks</source>
        <translation>최근 파단(&amp;R)</translation>
    </message>
    <message>
        <source>Simulation &amp;wireframe</source>
        <translation>시뮬레이션 와이어프레임(&amp;W)</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>위(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>앞(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation>등각(&amp;I)</translation>
    </message>
    <message>
        <source>Fit to &amp;sheet</source>
        <translation>시트에 맞추기(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Mouse and Keys</source>
        <translation>마우스와 키(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;About PaperFold</source>
        <translation>PaperFold 정보(&amp;A)</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>시스템 언어</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>실행 취소(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>다시 실행(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>일시 정지(&amp;P)</translation>
    </message>
    <message>
        <source>Sett&amp;le</source>
        <translation>안정시키기(&amp;L)</translation>
    </message>
    <message>
        <source>Let the sheet come to rest without new breaks and keep it so until the next edit (Ctrl+K)</source>
        <translation>새 파단 없이 시트를 멈추게 하고 다음 편집까지 그대로 둡니다 (Ctrl+K)</translation>
    </message>
    <message>
        <source>&amp;Push</source>
        <translation>누르기(&amp;P)</translation>
    </message>
    <message>
        <source>Push: the left button presses the sphere into the sheet and ploughs it (P)</source>
        <translation>누르기: 왼쪽 버튼으로 구를 종이에 눌러 넣고 밀어 갑니다 (P)</translation>
    </message>
    <message>
        <source>&amp;Grab</source>
        <translation>잡기(&amp;G)</translation>
    </message>
    <message>
        <source>Grab: pick up a point of the sheet and drag it; the wheel lifts or lowers it while held; release lets it fall (G)</source>
        <translation>잡기: 종이의 한 점을 집어 끌어 옮깁니다. 누르고 있는 동안 휠로 올리거나 내리고, 놓으면 떨어집니다 (G)</translation>
    </message>
    <message>
        <source>P&amp;in</source>
        <translation>고정(&amp;I)</translation>
    </message>
    <message>
        <source>Pin: a click pins the paper around the point, or frees it if it is pinned; Ctrl + wheel sizes the region (I)</source>
        <translation>고정: 클릭하면 그 점 주변의 종이를 고정하고, 이미 고정되어 있으면 풀어 줍니다. Ctrl + 휠로 영역 크기를 바꿉니다 (I)</translation>
    </message>
    <message>
        <source>Start the current scene again (Edit ▸ Undo gives it back)</source>
        <translation>현재 장면을 처음부터 다시 시작합니다 (편집 ▸ 실행 취소로 되돌릴 수 있음)</translation>
    </message>
    <message>
        <source>&amp;Fold (one edge turned over onto the other)</source>
        <translation>접기 (한쪽 끝을 다른 쪽 위로 넘김)(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Fold</source>
        <translation>접기(&amp;F)</translation>
    </message>
    <message>
        <source>Fold: draw a line across the paper; the lighter side (or the side without pins) is carried round it, pressed flat, opened to the angle set in the Parameters panel and let go (L)</source>
        <translation>접기: 종이를 가로지르는 선을 그립니다. 가벼운 쪽(또는 고정점이 없는 쪽)이 선을 따라 넘겨지고, 평평하게 눌린 뒤, 매개변수 패널에서 정한 각도까지 펼쳐지고 놓입니다 (L)</translation>
    </message>
    <message>
        <source>Cr&amp;umple Cycles (crumpled and pulled flat, ten times)</source>
        <translation>구기기 반복 (열 번 구겼다 펴기)(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Crease Lines</source>
        <translation>접힌 자국 선(&amp;C)</translation>
    </message>
    <message>
        <source>The paper&apos;s creases drawn as fine lines a shade darker than the paper, as the damaged fibres of a crease show, also once the paper is pulled flat</source>
        <translation>종이의 접힌 자국을 종이보다 조금 어두운 가는 선으로 그립니다. 접힌 곳의 상한 섬유처럼, 종이를 평평하게 편 뒤에도 보입니다</translation>
    </message>
</context>
<context>
    <name>pf::ChartBrowser</name>
    <message>
        <source>No bench_*.png in %1. Run: paperfold bench --output-dir %1</source>
        <translation>%1에 bench_*.png가 없습니다. 실행: paperfold bench --output-dir %1</translation>
    </message>
    <message>
        <source>No chart in %1 yet: choose the folder &apos;paperfold bench --output-dir&apos; wrote</source>
        <translation>%1에 아직 차트가 없습니다: &apos;paperfold bench --output-dir&apos;가 쓴 폴더를 고르세요</translation>
    </message>
</context>
<context>
    <name>pf::EditorDialogs</name>
    <message>
        <source>PaperFold sheets (*.paper)</source>
        <translation>PaperFold 시트 (*.paper)</translation>
    </message>
    <message>
        <source>Open Sheet</source>
        <translation>시트 열기</translation>
    </message>
    <message>
        <source>Save Sheet</source>
        <translation>시트 저장</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>이미지 내보내기</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 이미지 (*.png)</translation>
    </message>
    <message>
        <source>Export Mesh</source>
        <translation>메시 내보내기</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply *.glb)</source>
        <translation>메시 (*.obj *.ply *.glb)</translation>
    </message>
    <message>
        <source>Save Recording</source>
        <translation>기록 저장</translation>
    </message>
    <message>
        <source>PaperFold recordings (*.paperrec)</source>
        <translation>PaperFold 기록 (*.paperrec)</translation>
    </message>
    <message>
        <source>PaperFold</source>
        <translation>PaperFold</translation>
    </message>
    <message>
        <source>The sheet has unsaved changes. Save them?</source>
        <translation>시트에 저장하지 않은 변경 사항이 있습니다. 저장할까요?</translation>
    </message>
    <message>
        <source>Size in pixels (width x height):</source>
        <translation>픽셀 크기 (너비 x 높이):</translation>
    </message>
    <message>
        <source>Picture for the Paper</source>
        <translation>종이에 쓸 그림</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.bmp *.webp)</source>
        <translation>이미지 (*.png *.jpg *.jpeg *.bmp *.webp)</translation>
    </message>
    <message>
        <source>Paper Colour</source>
        <translation>종이 색</translation>
    </message>
    <message>
        <source>Subdivision level, 0 to %1: 0 writes the simulation mesh; each level splits every triangle in four along the paper&apos;s curved surface.</source>
        <translation>세분 단계 (0~%1): 0은 시뮬레이션 메시를 그대로 저장합니다. 단계마다 모든 삼각형을 종이의 곡면을 따라 넷으로 나눕니다.</translation>
    </message>
</context>
<context>
    <name>pf::HelpText</name>
    <message>
        <source>Mouse and Keys</source>
        <translation>마우스와 키</translation>
    </message>
    <message>
        <source>About PaperFold</source>
        <translation>PaperFold 정보</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;PaperFold %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Crumple and fold virtual paper in real time, after Kang &amp;amp; Cho, &lt;i&gt;A Simple and Effective Model for Interactive Paper Folding&lt;/i&gt;.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;PaperFold %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;가상의 종이를 실시간으로 구기고 접습니다. Kang &amp;amp; Cho, &lt;i&gt;A Simple and Effective Model for Interactive Paper Folding&lt;/i&gt;에 기반합니다.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;table cellspacing=&quot;2&quot; cellpadding=&quot;3&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;P&lt;/b&gt;, &lt;b&gt;G&lt;/b&gt;, &lt;b&gt;I&lt;/b&gt;, &lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;tools: push, grab, pin, fold&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (push)&lt;/td&gt;&lt;td&gt;press the sphere into the paper and plough it (one undo step per stroke)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (grab)&lt;/td&gt;&lt;td&gt;pick up the point under the cursor and drag it; the wheel lifts or lowers it while held; release lets it fall&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Click&lt;/b&gt; (pin)&lt;/td&gt;&lt;td&gt;pin the paper around the point, or free it if it is pinned&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (fold)&lt;/td&gt;&lt;td&gt;draw the fold line across the paper; the lighter side (or the side without pins) is carried round it (valley or mountain, and the angle, in the Parameters panel)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl + wheel&lt;/b&gt;&lt;/td&gt;&lt;td&gt;sphere radius (and the pin region)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Right drag&lt;/b&gt;, arrow keys&lt;/td&gt;&lt;td&gt;orbit the camera&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Middle drag&lt;/b&gt;, Shift + right drag&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Wheel&lt;/b&gt;, + and −&lt;/td&gt;&lt;td&gt;zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1&lt;/b&gt;, &lt;b&gt;2&lt;/b&gt;, &lt;b&gt;3&lt;/b&gt;, &lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;top, front, isometric view; fit to sheet&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Space&lt;/b&gt;, &lt;b&gt;Ctrl+.&lt;/b&gt;, &lt;b&gt;Ctrl+K&lt;/b&gt;, &lt;b&gt;Ctrl+R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;play/pause, single step, settle, reset&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt+1…5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;overlays: spring kinds, break probability, strain, recent breaks, wireframe&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt;, &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;undo, redo&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table cellspacing=&quot;2&quot; cellpadding=&quot;3&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;P&lt;/b&gt;, &lt;b&gt;G&lt;/b&gt;, &lt;b&gt;I&lt;/b&gt;, &lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;도구: 누르기, 잡기, 고정, 접기&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;왼쪽 드래그&lt;/b&gt; (누르기)&lt;/td&gt;&lt;td&gt;구를 종이에 눌러 넣고 밀어 갑니다 (한 번의 스트로크가 한 번의 실행 취소 단위)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;왼쪽 드래그&lt;/b&gt; (잡기)&lt;/td&gt;&lt;td&gt;커서 아래의 점을 집어 끌어 옮깁니다. 누르고 있는 동안 휠로 올리거나 내리고, 놓으면 떨어집니다&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;클릭&lt;/b&gt; (고정)&lt;/td&gt;&lt;td&gt;그 점 주변의 종이를 고정하거나, 고정되어 있으면 풀어 줍니다&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;왼쪽 드래그&lt;/b&gt; (접기)&lt;/td&gt;&lt;td&gt;종이를 가로지르는 접는 선을 그립니다. 가벼운 쪽(또는 고정점이 없는 쪽)이 선을 따라 넘겨집니다 (골접기/산접기와 각도는 매개변수 패널에서)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl + 휠&lt;/b&gt;&lt;/td&gt;&lt;td&gt;구 반지름 (및 고정 영역)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;오른쪽 드래그&lt;/b&gt;, 화살표 키&lt;/td&gt;&lt;td&gt;카메라 회전&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;가운데 드래그&lt;/b&gt;, Shift + 오른쪽 드래그&lt;/td&gt;&lt;td&gt;이동&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;휠&lt;/b&gt;, + 와 −&lt;/td&gt;&lt;td&gt;확대/축소&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1&lt;/b&gt;, &lt;b&gt;2&lt;/b&gt;, &lt;b&gt;3&lt;/b&gt;, &lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;위, 앞, 등각 보기; 종이에 맞추기&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Space&lt;/b&gt;, &lt;b&gt;Ctrl+.&lt;/b&gt;, &lt;b&gt;Ctrl+K&lt;/b&gt;, &lt;b&gt;Ctrl+R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;재생/일시 정지, 한 단계, 안정시키기, 초기화&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt+1…5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;오버레이: 스프링 종류, 파단 확률, 변형률, 최근 파단, 와이어프레임&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt;, &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;실행 취소, 다시 실행&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
</context>
<context>
    <name>pf::MainWindow</name>
    <message>
        <source>The simulation blew up at step %1 and was paused; the last good state is kept. Try more steps per second or the jacobi integrator.</source>
        <translation>%1 단계에서 시뮬레이션이 발산하여 일시 정지했습니다. 마지막 정상 상태는 유지됩니다. 초당 단계 수를 늘리거나 jacobi 적분기를 사용해 보세요.</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <source>Ctrl+.</source>
        <translation>Ctrl+.</translation>
    </message>
    <message>
        <source>Ctrl+R</source>
        <translation>Ctrl+R</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>파일(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>새로 만들기(&amp;N)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>최근 파일(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>편집(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>보기(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>오버레이(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>언어(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>시뮬레이션(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>도움말(&amp;H)</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>기본 도구 모음</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>매개변수</translation>
    </message>
    <message>
        <source>History</source>
        <translation>기록</translation>
    </message>
    <message>
        <source>&lt;new sheet&gt;</source>
        <translation>&lt;새 시트&gt;</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>제목 없음</translation>
    </message>
    <message>
        <source>%1[*] — PaperFold</source>
        <translation>%1[*] — PaperFold</translation>
    </message>
    <message>
        <source>Could not open the sheet: %1</source>
        <translation>시트를 열 수 없습니다: %1</translation>
    </message>
    <message>
        <source>Could not save the sheet: %1</source>
        <translation>시트를 저장할 수 없습니다: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 저장됨</translation>
    </message>
    <message>
        <source>Could not export the image: %1</source>
        <translation>이미지를 내보낼 수 없습니다: %1</translation>
    </message>
    <message>
        <source>Choose a file ending in .obj, .ply or .glb</source>
        <translation>.obj, .ply 또는 .glb로 끝나는 파일을 고르세요</translation>
    </message>
    <message>
        <source>Could not export the mesh: %1</source>
        <translation>메시를 내보낼 수 없습니다: %1</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>솔버</translation>
    </message>
    <message>
        <source>Could not save the recording: %1</source>
        <translation>기록을 저장할 수 없습니다: %1</translation>
    </message>
    <message>
        <source>Paused: the push moves the paper only while the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>일시 정지됨: 누르기는 시뮬레이션이 실행되는 동안에만 종이를 움직입니다 (Space 재생, Ctrl+. 한 단계).</translation>
    </message>
    <message>
        <source>The image size is width x height, each from 16 to %1 pixels, such as 1920x1080.</source>
        <translation>이미지 크기는 너비 x 높이이며, 각각 16~%1 픽셀입니다 (예: 1920x1080).</translation>
    </message>
    <message>
        <source>Settled: the sheet stays as it is until the next edit.</source>
        <translation>안정됨: 다음 편집까지 시트가 그대로 유지됩니다.</translation>
    </message>
    <message>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <source>Settling: the sheet comes to rest…</source>
        <translation>안정시키는 중: 시트가 멈추는 중…</translation>
    </message>
    <message>
        <source>Settling once the simulation plays (Space).</source>
        <translation>시뮬레이션이 재생되면 안정시킵니다 (Space).</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>도구(&amp;T)</translation>
    </message>
    <message>
        <source>Paused: the grab moves the paper only while the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>일시 정지됨: 잡기는 시뮬레이션이 실행되는 동안에만 종이를 움직입니다 (Space 재생, Ctrl+. 한 단계).</translation>
    </message>
    <message>
        <source>Rendering the image (%1 x %2)…</source>
        <translation>이미지를 렌더링하는 중 (%1 x %2)…</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>이미지 내보내기</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 내보냄</translation>
    </message>
    <message>
        <source>An image is being exported; close once it is written.</source>
        <translation>이미지를 내보내는 중입니다. 다 쓴 뒤에 닫으세요.</translation>
    </message>
    <message>
        <source>Paused: the fold is carried round once the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>일시 정지됨: 시뮬레이션이 재생되면 접기가 진행됩니다 (Space 재생, Ctrl+. 한 단계).</translation>
    </message>
    <message>
        <source>Left drag pushes the paper · L folds, G grabs and I pins (Tools menu) · right drag orbits · the wheel zooms · F1 lists every key</source>
        <translation>왼쪽 드래그로 종이 누르기 · L 접기, G 잡기, I 고정 (도구 메뉴) · 오른쪽 드래그로 회전 · 휠로 확대/축소 · F1 모든 키 보기</translation>
    </message>
    <message>
        <source>Folding: the paper is carried round the line, pressed and let go…</source>
        <translation>접는 중: 종이를 선을 따라 넘기고, 누르고, 놓습니다…</translation>
    </message>
    <message>
        <source>Not folded: draw a longer line across the paper.</source>
        <translation>접지 않음: 종이를 가로지르는 더 긴 선을 그리세요.</translation>
    </message>
    <message>
        <source>Not folded: the line must cross the paper.</source>
        <translation>접지 않음: 선이 종이를 가로질러야 합니다.</translation>
    </message>
    <message>
        <source>Not folded: there is paper on one side of the line only.</source>
        <translation>접지 않음: 선의 한쪽에만 종이가 있습니다.</translation>
    </message>
    <message>
        <source>Not folded: the angle must lie between 1° and 180°.</source>
        <translation>접지 않음: 각도는 1°에서 180° 사이여야 합니다.</translation>
    </message>
    <message>
        <source>Not folded: another edit is under way.</source>
        <translation>접지 않음: 다른 편집이 진행 중입니다.</translation>
    </message>
    <message>
        <source>Not folded: this way the flap would go through the desk, and pins hold the paper down. Fold the other way (Valley or Mountain), or unpin the paper.</source>
        <translation>접지 않음: 이 방향이면 접히는 부분이 책상을 뚫고 지나가는데, 고정점이 종이를 붙잡고 있어 들어 올릴 수 없습니다. 반대로 접거나 (골접기 또는 산접기) 고정을 푸세요.</translation>
    </message>
    <message>
        <source>Not folded: pins hold the paper on both sides of the line. Unpin one side: the pinned side stays, the other is folded over.</source>
        <translation>접지 않음: 선의 양쪽에서 고정점이 종이를 붙잡고 있습니다. 한쪽의 고정을 푸세요. 고정된 쪽은 그대로 있고 다른 쪽이 접힙니다.</translation>
    </message>
    <message>
        <source>Not now: a fold is under way.</source>
        <translation>지금은 할 수 없습니다: 접는 중입니다.</translation>
    </message>
    <message>
        <source>Folded. Edit ▸ Undo unfolds the paper.</source>
        <translation>접었습니다. 편집 ▸ 실행 취소로 종이를 펼칩니다.</translation>
    </message>
    <message>
        <source>The fold opened %1° again after it was let go: its crease did not hold the flap. Edit ▸ Undo unfolds the paper.</source>
        <translation>놓은 뒤 접힘이 다시 %1° 열렸습니다: 접힌 자국이 날개를 붙잡지 못했습니다. 편집 ▸ 실행 취소로 종이를 펼칩니다.</translation>
    </message>
    <message>
        <source>Only part of the fold held: %1 % of the paper on the flap&apos;s side lies unfolded. The fold holds the paper that lies flat along the line, not layers above or below it. Edit ▸ Undo unfolds the paper.</source>
        <translation>접힘이 일부만 유지되었습니다: 날개 쪽 종이의 %1 %가 접히지 않은 채 놓여 있습니다. 접기는 선을 따라 평평하게 놓인 종이를 붙잡으며, 그 위나 아래의 층은 붙잡지 않습니다. 편집 ▸ 실행 취소로 종이를 펼칩니다.</translation>
    </message>
    <message>
        <source>Already settled: the sheet stays as it is until the next edit.</source>
        <translation>이미 안정됨: 다음 편집까지 시트가 그대로 유지됩니다.</translation>
    </message>
    <message>
        <source>Not settled: an edit is under way. Settle once it is over.</source>
        <translation>안정시킬 수 없습니다: 편집 중입니다. 편집이 끝난 뒤 안정시키세요.</translation>
    </message>
    <message>
        <source>The fold is opening again: its crease does not hold the flap. Edit ▸ Undo unfolds the paper.</source>
        <translation>접힘이 다시 열리고 있습니다: 접힌 자국이 날개를 붙잡지 못합니다. 편집 ▸ 실행 취소로 종이를 펼칩니다.</translation>
    </message>
    <message>
        <source>The fold fell shut after it was let go: its crease cannot hold the flap up at %1°. Edit ▸ Undo unfolds the paper.</source>
        <translation>놓은 뒤 접힘이 닫혀 버렸습니다: 접힌 자국이 %1°에서 날개를 세워 두지 못합니다. 편집 ▸ 실행 취소로 종이를 펼칩니다.</translation>
    </message>
    <message>
        <source>The fold closed %1° further than asked after it was let go: its crease cannot hold the flap at that angle. Edit ▸ Undo unfolds the paper.</source>
        <translation>놓은 뒤 접힘이 요청보다 %1° 더 닫혔습니다: 접힌 자국이 그 각도에서 날개를 붙잡지 못합니다. 편집 ▸ 실행 취소로 종이를 펼칩니다.</translation>
    </message>
    <message>
        <source>Undo waits until the fold is let go.</source>
        <translation>실행 취소는 접기가 손을 떠날 때까지 기다립니다.</translation>
    </message>
    <message>
        <source>Undo waits until the sheet has settled.</source>
        <translation>실행 취소는 종이가 멈출 때까지 기다립니다.</translation>
    </message>
    <message>
        <source>Undo waits until the mouse lets go of the paper.</source>
        <translation>실행 취소는 마우스가 종이를 놓을 때까지 기다립니다.</translation>
    </message>
    <message>
        <source>Paused: the fold waits. Space plays and carries the paper round the line; Ctrl+. steps.</source>
        <translation>일시 정지됨: 접기가 기다리고 있습니다. Space를 누르면 재생되어 종이가 선을 따라 접힙니다. Ctrl+. 한 단계.</translation>
    </message>
    <message>
        <source>Undo waits until the fold is let go, and the simulation is paused: Space plays.</source>
        <translation>실행 취소는 접기가 손을 떠날 때까지 기다리며, 시뮬레이션이 일시 정지되어 있습니다: Space 재생.</translation>
    </message>
    <message>
        <source>The pins hold this paper taut: the hand pulls it with at most %1 N, as a pinch does before paper slips from it, and paper does not stretch to follow.</source>
        <translation>고정점이 이 종이를 팽팽하게 잡고 있습니다. 손은 최대 %1 N으로 당기며(그 이상이면 집은 종이가 손가락에서 미끄러집니다), 종이는 늘어나서 따라오지 않습니다.</translation>
    </message>
    <message>
        <source>This push moved nothing: the tool touched no paper, or slid over paper it cannot move (paper held by pins, say). Push where the paper is free, or unpin it.</source>
        <translation>이번 누르기로는 아무것도 움직이지 않았습니다. 도구가 종이에 닿지 않았거나, 움직일 수 없는 종이(고정점으로 잡힌 종이 등) 위를 미끄러졌습니다. 종이가 자유로운 곳을 누르거나 고정을 푸세요.</translation>
    </message>
    <message>
        <source>Not now: the mouse holds the paper. Let go first.</source>
        <translation>지금은 할 수 없습니다: 마우스가 종이를 잡고 있습니다. 먼저 놓으세요.</translation>
    </message>
    <message>
        <source>&lt;new: %1&gt;</source>
        <translation>&lt;새 시트: %1&gt;</translation>
    </message>
</context>
<context>
    <name>pf::PaperLookMenu</name>
    <message>
        <source>Could not use the picture as paper: %1</source>
        <translation>이 그림을 종이로 쓸 수 없습니다: %1</translation>
    </message>
    <message>
        <source>&amp;Paper</source>
        <translation>종이(&amp;P)</translation>
    </message>
    <message>
        <source>Paper &amp;Colour…</source>
        <translation>종이 색(&amp;C)…</translation>
    </message>
    <message>
        <source>&amp;Plain</source>
        <translation>무늬 없음(&amp;P)</translation>
    </message>
    <message>
        <source>Paper &amp;Grain</source>
        <translation>종이 결(&amp;G)</translation>
    </message>
    <message>
        <source>P&amp;icture: %1…</source>
        <translation>그림(&amp;I): %1…</translation>
    </message>
    <message>
        <source>P&amp;icture…</source>
        <translation>그림(&amp;I)…</translation>
    </message>
    <message>
        <source>Print a picture over the whole sheet</source>
        <translation>시트 전체에 그림을 인쇄합니다</translation>
    </message>
</context>
<context>
    <name>pf::ParameterPanel</name>
    <message>
        <source>φ fragility</source>
        <translation>φ 취성</translation>
    </message>
    <message>
        <source>Fragility φ scales the normal dot products of the break probability (Eq. 10). Larger φ: stiffer paper that breaks only where it is already curved; at 1 a flat region never breaks. Smaller φ: softer paper that crumples anywhere it is compressed.</source>
        <translation>취성 φ는 파단 확률(식 10)에서 법선 내적에 곱하는 값입니다. φ가 크면 종이가 단단해져 이미 휘어진 곳에서만 파단되며, 1이면 평평한 곳은 절대 파단되지 않습니다. φ가 작으면 종이가 부드러워져 압축되는 곳 어디서나 구겨집니다.</translation>
    </message>
    <message>
        <source>ψ recursive break</source>
        <translation>ψ 재귀 파단</translation>
    </message>
    <message>
        <source>ψ sets how far a new vertex moves out of the surface when a spring breaks (Eq. 11). At 1 the two halves keep the rest length and do not break again at once; smaller ψ leaves them compressed, so breaks repeat into finer crumples.</source>
        <translation>ψ는 스프링이 파단될 때 새 정점이 면 밖으로 얼마나 나오는지 정합니다(식 11). 1이면 두 반쪽이 정지 길이를 유지해 곧바로 다시 파단되지 않고, ψ가 작으면 압축된 채로 남아 파단이 반복되며 더 잘게 구겨집니다.</translation>
    </message>
    <message>
        <source>σ shapes the subdivided surface that is drawn (§4.3): 0 keeps flat facets and sharp creases, larger values round them off. It does not change the simulation.</source>
        <translation>σ는 그려지는 세분화 곡면의 모양을 정합니다(§4.3). 0이면 평평한 면과 날카로운 주름이 그대로이고, 값이 클수록 둥글게 다듬어집니다. 시뮬레이션은 바뀌지 않습니다.</translation>
    </message>
    <message>
        <source>Tool radius</source>
        <translation>도구 반지름</translation>
    </message>
    <message>
        <source>Radius of the sphere you push the paper with (Ctrl+wheel in the view).</source>
        <translation>종이를 누르는 구의 반지름 (보기에서 Ctrl+휠).</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>Advanced</source>
        <translation>고급</translation>
    </message>
    <message>
        <source>Stretch stiffness</source>
        <translation>인장 강성</translation>
    </message>
    <message>
        <source>Bending stiffness</source>
        <translation>굽힘 강성</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>해상도</translation>
    </message>
    <message>
        <source>Vertices along the sheet&apos;s short side.</source>
        <translation>시트 짧은 변을 따라 놓인 정점 수.</translation>
    </message>
    <message>
        <source>Sheet size</source>
        <translation>시트 크기</translation>
    </message>
    <message>
        <source>Resolution and size apply to the next New or Reset.</source>
        <translation>해상도와 크기는 다음 새로 만들기나 초기화 때 적용됩니다.</translation>
    </message>
    <message>
        <source>Push depth</source>
        <translation>누르는 깊이</translation>
    </message>
    <message>
        <source>How deep a push presses the sphere into the paper, as a share of its radius: deeper pushes crease harder.</source>
        <translation>누를 때 구를 종이에 얼마나 깊이 눌러 넣을지, 반지름에 대한 비율입니다. 깊을수록 더 강하게 접힙니다.</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>접기</translation>
    </message>
    <message>
        <source>Valley</source>
        <translation>골접기</translation>
    </message>
    <message>
        <source>Mountain</source>
        <translation>산접기</translation>
    </message>
    <message>
        <source>The Fold tool (L): draw a line across the paper; the lighter side (or the side without pins) is carried round it, pressed flat, opened to this angle and let go. A valley fold turns the flap up toward you, a mountain fold away from you, under the paper.</source>
        <translation>접기 도구 (L): 종이를 가로지르는 선을 그립니다. 가벼운 쪽(또는 고정점이 없는 쪽)이 선을 따라 넘겨지고, 평평하게 눌린 뒤, 이 각도까지 펼쳐지고 놓입니다. 골접기는 접히는 부분을 내 쪽(위)으로, 산접기는 반대쪽(종이 아래)으로 접습니다.</translation>
    </message>
    <message>
        <source>σ crumple smoothing</source>
        <translation>σ 주름 부드러움</translation>
    </message>
</context>
<context>
    <name>pf::SolverPanel</name>
    <message>
        <source>tissue</source>
        <translation>티슈</translation>
    </message>
    <message>
        <source>office</source>
        <translation>사무용지</translation>
    </message>
    <message>
        <source>card</source>
        <translation>판지</translation>
    </message>
    <message>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <source>max %1 %, RMS %2 %</source>
        <translation>최대 %1 %, RMS %2 %</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>적분기</translation>
    </message>
    <message>
        <source>Jacobi sweeps</source>
        <translation>야코비 반복 횟수</translation>
    </message>
    <message>
        <source>Steps per second</source>
        <translation>초당 단계 수</translation>
    </message>
    <message>
        <source>Cores used</source>
        <translation>사용 코어 수</translation>
    </message>
    <message numerus="yes">
        <source>How many of this computer&apos;s %n cores step the sheet. The sheet moves the same, to the last bit, on any number; by default one core is left to draw the view.</source>
        <translation>
            <numerusform>이 컴퓨터의 코어 %n개 중 종이를 계산하는 데 쓰는 수. 어떤 수로도 종이는 마지막 비트까지 똑같이 움직입니다. 기본값은 보기를 그리는 데 코어 하나를 남겨 둡니다.</numerusform>
        </translation>
    </message>
    <message>
        <source>Gravity outside the implicit filter</source>
        <translation>중력을 암시적 필터 밖에서 적분</translation>
    </message>
    <message>
        <source>Start the Jacobi iteration at Δv = h·g. The paper&apos;s step divides gravity by W, so a hanging sheet falls at a fraction of g; this keeps free fall exact at the same stability.</source>
        <translation>야코비 반복을 Δv = h·g에서 시작합니다. 논문의 단계는 중력을 W로 나누어 매달린 시트가 g의 일부 가속도로만 떨어집니다. 이렇게 하면 안정성은 그대로이면서 자유 낙하가 정확해집니다.</translation>
    </message>
    <message>
        <source>Step time</source>
        <translation>단계 시간</translation>
    </message>
    <message>
        <source>Stretch</source>
        <translation>늘어남</translation>
    </message>
    <message>
        <source>max(l/l0 - 1, 0) over the uncreased structural springs, live: how far the paper is pulled longer (edges that paper bending between two vertices shortens do not count)</source>
        <translation>접히지 않은 구조 스프링의 max(l/l0 - 1, 0) (실시간): 종이가 얼마나 늘어났는지 (두 꼭짓점 사이에서 종이가 휘어 짧아진 변은 세지 않음)</translation>
    </message>
    <message>
        <source>Open Latest Chart…</source>
        <translation>최신 차트 열기…</translation>
    </message>
    <message>
        <source>Show the newest speed–accuracy chart written by &apos;paperfold bench&apos;.</source>
        <translation>&apos;paperfold bench&apos;가 만든 최신 속도-정확도 차트를 보여 줍니다.</translation>
    </message>
    <message>
        <source>jacobi: the paper&apos;s approximate implicit step (Eq. 6); jacobi-scalar: the same with k·I blocks; symplectic: explicit; backward-euler: the exact implicit step (slow, the reference); xpbd: paper from its physical constants (docs/material.md).</source>
        <translation>jacobi: 논문의 근사 암시적 단계 (식 6); jacobi-scalar: k·I 블록을 쓰는 같은 방법; symplectic: 명시적; backward-euler: 정확한 암시적 단계 (느림, 기준); xpbd: 물리 상수로 만든 종이 (docs/material.md).</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>종이</translation>
    </message>
    <message>
        <source>The paper&apos;s weight, stretch and bending stiffness and friction, used by the xpbd integrator: tissue 20 g/m², office 80 g/m², card 250 g/m².</source>
        <translation>xpbd 적분기가 쓰는 종이의 무게, 늘임 강성, 굽힘 강성, 마찰: 티슈 20 g/m², 사무용지 80 g/m², 판지 250 g/m².</translation>
    </message>
    <message numerus="yes">
        <source>%n per second</source>
        <translation>
            <numerusform>초당 %n</numerusform>
        </translation>
    </message>
    <message>
        <source>Breaks</source>
        <translation>파단</translation>
    </message>
    <message>
        <source>Breaks in the last second of simulated time: paper breaks while it is loaded further, and stops when the load stops</source>
        <translation>시뮬레이션 시간 최근 1초 동안의 파단 수: 종이는 하중이 더 커지는 동안 파단되고, 하중이 멈추면 파단도 멈춥니다</translation>
    </message>
    <message>
        <source>How many steps one simulated second takes (the step h = 1/N s). More steps are more accurate and cost more: the sheet moves in real time while the computer can take them that fast. The paper&apos;s behaviour is checked at 240 (&apos;paperfold fidelity&apos;).</source>
        <translation>시뮬레이션 1초당 스텝 수(스텝 크기 h = 1/N 초). 스텝이 많을수록 정확하지만 계산이 더 듭니다. 컴퓨터가 그 속도로 계산할 수 있는 동안 종이는 실시간으로 움직입니다. 종이의 거동은 240에서 검증되었습니다(&apos;paperfold fidelity&apos;).</translation>
    </message>
</context>
<context>
    <name>pf::StatusReadout</name>
    <message>
        <source>%1 · paused</source>
        <translation>%1 · 일시 정지됨</translation>
    </message>
    <message>
        <source>In brackets: the breaks in the last second of simulated time, which lasts longer than a second on the clock while the sheet runs behind real time</source>
        <translation>괄호 안: 시뮬레이션 시간 최근 1초 동안의 파단 수. 시트가 실시간보다 느리게 움직이는 동안 이 1초는 시계로는 1초보다 오래 걸립니다</translation>
    </message>
    <message>
        <source>%1 · %2× real time</source>
        <translation>%1 · 실시간의 %2배</translation>
    </message>
    <message>
        <source>The computer cannot take the steps as fast as they happen: the sheet moves slower than in real time. Fewer steps per second (Solver dock), a smaller sheet or another integrator are faster.</source>
        <translation>컴퓨터가 시간에 맞춰 스텝을 계산하지 못합니다. 종이가 실시간보다 느리게 움직입니다. 초당 단계 수를 줄이거나(솔버 패널), 더 작은 종이나 다른 적분기를 쓰면 빨라집니다.</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 fps</translation>
    </message>
    <message>
        <source>step %1 µs</source>
        <translation>단계 %1 µs</translation>
    </message>
    <message>
        <source>%1 · at rest</source>
        <translation>%1 · 정지</translation>
    </message>
    <message>
        <source>%1 vertices · %2 springs · %3 (%4/s) · %5</source>
        <translation>정점 %1 · 스프링 %2 · %3 (%4/초) · %5</translation>
    </message>
    <message numerus="yes">
        <source>%n break(s)</source>
        <translation>
            <numerusform>파단 %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n hinge(s)</source>
        <translation>
            <numerusform>힌지 %n</numerusform>
        </translation>
    </message>
    <message>
        <source>no step yet</source>
        <translation>아직 단계 없음</translation>
    </message>
    <message>
        <source>at rest</source>
        <translation>정지</translation>
    </message>
    <message>
        <source>settled</source>
        <translation>안정됨</translation>
    </message>
    <message>
        <source>%1 · settled</source>
        <translation>%1 · 안정됨</translation>
    </message>
    <message>
        <source>– fps</source>
        <translation>– fps</translation>
    </message>
    <message>
        <source>Nothing moves, so the view is not drawn again until something changes.</source>
        <translation>움직이는 것이 없어 무언가 바뀔 때까지 화면을 다시 그리지 않습니다.</translation>
    </message>
</context>
<context>
    <name>pf::StrokeHistory</name>
    <message>
        <source>Could not undo “%1”: the paper is no longer as this step left it.</source>
        <translation>“%1”을(를) 실행 취소할 수 없습니다: 종이가 더 이상 이 단계가 끝났을 때의 상태가 아닙니다.</translation>
    </message>
    <message>
        <source>Could not redo “%1”: the paper is no longer as this step found it.</source>
        <translation>“%1”을(를) 다시 실행할 수 없습니다: 종이가 더 이상 이 단계가 시작될 때의 상태가 아닙니다.</translation>
    </message>
</context>
<context>
    <name>pf::Viewport</name>
    <message>
        <source>OpenGL 3.3 is not available (missing %1)</source>
        <translation>OpenGL 3.3을 사용할 수 없습니다 (%1 없음)</translation>
    </message>
</context>
</TS>
