<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja">
<context>
    <name>Legend</name>
    <message>
        <source>simulation mesh (edges)</source>
        <translation>シミュレーションメッシュ（辺）</translation>
    </message>
    <message>
        <source>Break probability P (Eq. 10, per %1 % more contraction)</source>
        <translation>破断確率 P（式10、収縮が %1 % 増えるごと）</translation>
    </message>
    <message>
        <source>breakable spring</source>
        <translation>破断可能なばね</translation>
    </message>
    <message>
        <source>unbreakable spring</source>
        <translation>破断しないばね</translation>
    </message>
    <message>
        <source>crease (broken)</source>
        <translation>折り目（破断済み）</translation>
    </message>
    <message>
        <source>hinge</source>
        <translation>ヒンジ</translation>
    </message>
    <message>
        <source>broken in the last second</source>
        <translation>直近1秒の破断</translation>
    </message>
    <message>
        <source>Strain |l/l0 - 1|, stretched or compressed</source>
        <translation>ひずみ |l/l0 - 1|（伸びまたは縮み）</translation>
    </message>
</context>
<context>
    <name>UndoCommands</name>
    <message numerus="yes">
        <source>Push (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>押し込み（破断・ヒンジ %n 件）</numerusform>
        </translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1を変更</translation>
    </message>
    <message>
        <source>stretch stiffness</source>
        <translation>引張り剛性</translation>
    </message>
    <message>
        <source>bending stiffness</source>
        <translation>曲げ剛性</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>積分法</translation>
    </message>
    <message>
        <source>paper</source>
        <translation>紙</translation>
    </message>
    <message>
        <source>Jacobi sweeps</source>
        <translation>ヤコビ反復回数</translation>
    </message>
    <message>
        <source>steps per second</source>
        <translation>1秒あたりのステップ数</translation>
    </message>
    <message>
        <source>gravity outside the filter</source>
        <translation>フィルター外の重力</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>折る</translation>
    </message>
    <message>
        <source>Settle</source>
        <translation>静止</translation>
    </message>
    <message numerus="yes">
        <source>Grab (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>つかむ（破断・ヒンジ %n 件）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Pin %n vertex(es)</source>
        <translation>
            <numerusform>ピン留め（頂点 %n 個）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Unpin %n vertex(es)</source>
        <translation>
            <numerusform>ピン解除（頂点 %n 個）</numerusform>
        </translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>リセット</translation>
    </message>
    <message numerus="yes">
        <source>Fold (%n break(s) or hinge(s))</source>
        <translation>
            <numerusform>折る（破断・ヒンジ %n 件）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pf::ActionTexts</name>
    <message>
        <source>&amp;Press (sphere on a sheet)</source>
        <translation>押す（シート上の球）(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Drape (hanging sheet)</source>
        <translation>垂れ下がり（吊るしたシート）(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Compress (edges pushed together)</source>
        <translation>圧縮（両端を押し寄せる）(&amp;C)</translation>
    </message>
    <message>
        <source>D&amp;rop (tilted sheet falls)</source>
        <translation>落下（傾いたシートが落ちる）(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>開く(&amp;O)…</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>名前を付けて保存(&amp;A)…</translation>
    </message>
    <message>
        <source>Save &amp;Recording…</source>
        <translation>記録を保存(&amp;R)…</translation>
    </message>
    <message>
        <source>Save everything done since New or Open; paperfold replay does it again</source>
        <translation>新規または開く以降の操作をすべて保存します。paperfold replay で再現できます</translation>
    </message>
    <message>
        <source>Export &amp;Image…</source>
        <translation>画像を書き出す(&amp;I)…</translation>
    </message>
    <message>
        <source>Export &amp;Mesh…</source>
        <translation>メッシュを書き出す(&amp;M)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>再生(&amp;P)</translation>
    </message>
    <message>
        <source>Play or pause the simulation (Space)</source>
        <translation>シミュレーションを再生/一時停止（Space）</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>ステップ(&amp;T)</translation>
    </message>
    <message>
        <source>Advance one step</source>
        <translation>1ステップ進める</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>リセット(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Spring kinds</source>
        <translation>ばねの種類(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Break probability</source>
        <translation>破断確率(&amp;B)</translation>
    </message>
    <message>
        <source>S&amp;train</source>
        <translation>ひずみ(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Recent breaks</source>
        <translation>最近の破断(&amp;R)</translation>
    </message>
    <message>
        <source>Simulation &amp;wireframe</source>
        <translation>シミュレーションのワイヤーフレーム(&amp;W)</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>上面(&amp;T)</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>正面(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation>等角(&amp;I)</translation>
    </message>
    <message>
        <source>Fit to &amp;sheet</source>
        <translation>シートに合わせる(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Mouse and Keys</source>
        <translation>マウスとキー(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;About PaperFold</source>
        <translation>PaperFold について(&amp;A)</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>システムの言語</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>元に戻す(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>やり直し(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>一時停止(&amp;P)</translation>
    </message>
    <message>
        <source>Sett&amp;le</source>
        <translation>静止させる(&amp;L)</translation>
    </message>
    <message>
        <source>Let the sheet come to rest without new breaks and keep it so until the next edit (Ctrl+K)</source>
        <translation>新たな破断なしにシートを静止させ、次の編集までそのまま保ちます (Ctrl+K)</translation>
    </message>
    <message>
        <source>&amp;Push</source>
        <translation>押す(&amp;P)</translation>
    </message>
    <message>
        <source>Push: the left button presses the sphere into the sheet and ploughs it (P)</source>
        <translation>押す：左ボタンで球を紙に押し込み、紙をかき分けます (P)</translation>
    </message>
    <message>
        <source>&amp;Grab</source>
        <translation>つかむ(&amp;G)</translation>
    </message>
    <message>
        <source>Grab: pick up a point of the sheet and drag it; the wheel lifts or lowers it while held; release lets it fall (G)</source>
        <translation>つかむ：紙の一点をつまんでドラッグします。押している間はホイールで上げ下げでき、離すと落ちます (G)</translation>
    </message>
    <message>
        <source>P&amp;in</source>
        <translation>ピン留め(&amp;I)</translation>
    </message>
    <message>
        <source>Pin: a click pins the paper around the point, or frees it if it is pinned; Ctrl + wheel sizes the region (I)</source>
        <translation>ピン留め：クリックでその点の周りの紙を固定し、固定済みなら解除します。Ctrl + ホイールで範囲の大きさを変えます (I)</translation>
    </message>
    <message>
        <source>Start the current scene again (Edit ▸ Undo gives it back)</source>
        <translation>現在のシーンを最初からやり直します (編集 ▸ 元に戻す で戻せます)</translation>
    </message>
    <message>
        <source>&amp;Fold (one edge turned over onto the other)</source>
        <translation>折る（片方の端をもう一方に重ねる）(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Fold</source>
        <translation>折る(&amp;F)</translation>
    </message>
    <message>
        <source>Fold: draw a line across the paper; the lighter side (or the side without pins) is carried round it, pressed flat, opened to the angle set in the Parameters panel and let go (L)</source>
        <translation>折る：紙を横切る線を引きます。軽い側（またはピンのない側）が線のまわりに運ばれ、平らに押さえられ、パラメーターパネルで設定した角度まで開かれてから放されます（L）</translation>
    </message>
    <message>
        <source>Cr&amp;umple Cycles (crumpled and pulled flat, ten times)</source>
        <translation>くしゃくしゃ反復（10回丸めて平らに戻す）(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Crease Lines</source>
        <translation>折り目の線(&amp;C)</translation>
    </message>
    <message>
        <source>The paper&apos;s creases drawn as fine lines a shade darker than the paper, as the damaged fibres of a crease show, also once the paper is pulled flat</source>
        <translation>紙の折り目を、紙より少し濃い細い線で描きます。折り目の傷んだ繊維が見せるように、紙を平らに伸ばした後も残ります</translation>
    </message>
</context>
<context>
    <name>pf::ChartBrowser</name>
    <message>
        <source>No bench_*.png in %1. Run: paperfold bench --output-dir %1</source>
        <translation>%1 に bench_*.png がありません。次を実行してください：paperfold bench --output-dir %1</translation>
    </message>
    <message>
        <source>No chart in %1 yet: choose the folder &apos;paperfold bench --output-dir&apos; wrote</source>
        <translation>%1 にはまだグラフがありません：&apos;paperfold bench --output-dir&apos; が書き出したフォルダーを選んでください</translation>
    </message>
</context>
<context>
    <name>pf::EditorDialogs</name>
    <message>
        <source>PaperFold sheets (*.paper)</source>
        <translation>PaperFold シート (*.paper)</translation>
    </message>
    <message>
        <source>Open Sheet</source>
        <translation>シートを開く</translation>
    </message>
    <message>
        <source>Save Sheet</source>
        <translation>シートを保存</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>画像を書き出す</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 画像 (*.png)</translation>
    </message>
    <message>
        <source>Export Mesh</source>
        <translation>メッシュを書き出す</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply *.glb)</source>
        <translation>メッシュ (*.obj *.ply *.glb)</translation>
    </message>
    <message>
        <source>Save Recording</source>
        <translation>記録を保存</translation>
    </message>
    <message>
        <source>PaperFold recordings (*.paperrec)</source>
        <translation>PaperFold 記録 (*.paperrec)</translation>
    </message>
    <message>
        <source>PaperFold</source>
        <translation>PaperFold</translation>
    </message>
    <message>
        <source>The sheet has unsaved changes. Save them?</source>
        <translation>シートに未保存の変更があります。保存しますか？</translation>
    </message>
    <message>
        <source>Size in pixels (width x height):</source>
        <translation>ピクセル単位のサイズ（幅 x 高さ）：</translation>
    </message>
    <message>
        <source>Picture for the Paper</source>
        <translation>紙に使う画像</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.bmp *.webp)</source>
        <translation>画像 (*.png *.jpg *.jpeg *.bmp *.webp)</translation>
    </message>
    <message>
        <source>Paper Colour</source>
        <translation>紙の色</translation>
    </message>
    <message>
        <source>Subdivision level, 0 to %1: 0 writes the simulation mesh; each level splits every triangle in four along the paper&apos;s curved surface.</source>
        <translation>細分割レベル (0〜%1): 0 はシミュレーションのメッシュをそのまま書き出します。レベルが1つ上がるごとに、各三角形を紙の曲面に沿って4つに分割します。</translation>
    </message>
</context>
<context>
    <name>pf::HelpText</name>
    <message>
        <source>Mouse and Keys</source>
        <translation>マウスとキー</translation>
    </message>
    <message>
        <source>About PaperFold</source>
        <translation>PaperFold について</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;PaperFold %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Crumple and fold virtual paper in real time, after Kang &amp;amp; Cho, &lt;i&gt;A Simple and Effective Model for Interactive Paper Folding&lt;/i&gt;.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;PaperFold %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;仮想の紙をリアルタイムでくしゃくしゃにし、折ります。Kang &amp;amp; Cho『A Simple and Effective Model for Interactive Paper Folding』に基づきます。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;table cellspacing=&quot;2&quot; cellpadding=&quot;3&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;P&lt;/b&gt;, &lt;b&gt;G&lt;/b&gt;, &lt;b&gt;I&lt;/b&gt;, &lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;tools: push, grab, pin, fold&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (push)&lt;/td&gt;&lt;td&gt;press the sphere into the paper and plough it (one undo step per stroke)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (grab)&lt;/td&gt;&lt;td&gt;pick up the point under the cursor and drag it; the wheel lifts or lowers it while held; release lets it fall&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Click&lt;/b&gt; (pin)&lt;/td&gt;&lt;td&gt;pin the paper around the point, or free it if it is pinned&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Left drag&lt;/b&gt; (fold)&lt;/td&gt;&lt;td&gt;draw the fold line across the paper; the lighter side (or the side without pins) is carried round it (valley or mountain, and the angle, in the Parameters panel)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl + wheel&lt;/b&gt;&lt;/td&gt;&lt;td&gt;sphere radius (and the pin region)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Right drag&lt;/b&gt;, arrow keys&lt;/td&gt;&lt;td&gt;orbit the camera&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Middle drag&lt;/b&gt;, Shift + right drag&lt;/td&gt;&lt;td&gt;pan&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Wheel&lt;/b&gt;, + and −&lt;/td&gt;&lt;td&gt;zoom&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1&lt;/b&gt;, &lt;b&gt;2&lt;/b&gt;, &lt;b&gt;3&lt;/b&gt;, &lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;top, front, isometric view; fit to sheet&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Space&lt;/b&gt;, &lt;b&gt;Ctrl+.&lt;/b&gt;, &lt;b&gt;Ctrl+K&lt;/b&gt;, &lt;b&gt;Ctrl+R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;play/pause, single step, settle, reset&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt+1…5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;overlays: spring kinds, break probability, strain, recent breaks, wireframe&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt;, &lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;undo, redo&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table cellspacing=&quot;2&quot; cellpadding=&quot;3&quot;&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;P&lt;/b&gt;、&lt;b&gt;G&lt;/b&gt;、&lt;b&gt;I&lt;/b&gt;、&lt;b&gt;L&lt;/b&gt;&lt;/td&gt;&lt;td&gt;ツール：押す、つかむ、ピン留め、折る&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;左ドラッグ&lt;/b&gt;（押す）&lt;/td&gt;&lt;td&gt;球を紙に押し込んでかき分けます（1ストロークで1回の取り消し単位）&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;左ドラッグ&lt;/b&gt;（つかむ）&lt;/td&gt;&lt;td&gt;カーソルの下の点をつまんでドラッグします。押している間はホイールで上げ下げでき、離すと落ちます&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;クリック&lt;/b&gt;（ピン留め）&lt;/td&gt;&lt;td&gt;その点の周りの紙を固定します。固定済みなら解除します&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;左ドラッグ&lt;/b&gt;（折る）&lt;/td&gt;&lt;td&gt;紙を横切る折り線を引きます。軽い側（またはピンのない側）が線のまわりに運ばれます（谷折り・山折りと角度はパラメーターパネルで）&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl + ホイール&lt;/b&gt;&lt;/td&gt;&lt;td&gt;球の半径（とピン留めの範囲）&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;右ドラッグ&lt;/b&gt;、矢印キー&lt;/td&gt;&lt;td&gt;カメラを回転&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;中ドラッグ&lt;/b&gt;、Shift + 右ドラッグ&lt;/td&gt;&lt;td&gt;パン&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;ホイール&lt;/b&gt;、+ と −&lt;/td&gt;&lt;td&gt;ズーム&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;1&lt;/b&gt;、&lt;b&gt;2&lt;/b&gt;、&lt;b&gt;3&lt;/b&gt;、&lt;b&gt;F&lt;/b&gt;&lt;/td&gt;&lt;td&gt;上面・正面・等角ビュー、シートに合わせる&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Space&lt;/b&gt;、&lt;b&gt;Ctrl+.&lt;/b&gt;、&lt;b&gt;Ctrl+K&lt;/b&gt;、&lt;b&gt;Ctrl+R&lt;/b&gt;&lt;/td&gt;&lt;td&gt;再生/一時停止、1ステップ、静止させる、リセット&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Alt+1…5&lt;/b&gt;&lt;/td&gt;&lt;td&gt;オーバーレイ：ばねの種類、破断確率、ひずみ、最近の破断、ワイヤーフレーム&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;&lt;b&gt;Ctrl+Z&lt;/b&gt;、&lt;b&gt;Ctrl+Shift+Z&lt;/b&gt;&lt;/td&gt;&lt;td&gt;元に戻す、やり直し&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
</context>
<context>
    <name>pf::MainWindow</name>
    <message>
        <source>The simulation blew up at step %1 and was paused; the last good state is kept. Try more steps per second or the jacobi integrator.</source>
        <translation>ステップ %1 でシミュレーションが発散したため一時停止しました。最後の正常な状態は保持されています。1秒あたりのステップ数を増やすか、jacobi 積分器を試してください。</translation>
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
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>新規(&amp;N)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近使ったファイル(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>編集(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>オーバーレイ(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>言語(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>シミュレーション(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>メインツールバー</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>パラメーター</translation>
    </message>
    <message>
        <source>History</source>
        <translation>履歴</translation>
    </message>
    <message>
        <source>&lt;new sheet&gt;</source>
        <translation>&lt;新しいシート&gt;</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <source>%1[*] — PaperFold</source>
        <translation>%1[*] — PaperFold</translation>
    </message>
    <message>
        <source>Could not open the sheet: %1</source>
        <translation>シートを開けませんでした：%1</translation>
    </message>
    <message>
        <source>Could not save the sheet: %1</source>
        <translation>シートを保存できませんでした：%1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
    <message>
        <source>Could not export the image: %1</source>
        <translation>画像を書き出せませんでした：%1</translation>
    </message>
    <message>
        <source>Choose a file ending in .obj, .ply or .glb</source>
        <translation>.obj、.ply、.glb で終わるファイルを選んでください</translation>
    </message>
    <message>
        <source>Could not export the mesh: %1</source>
        <translation>メッシュを書き出せませんでした：%1</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>ソルバー</translation>
    </message>
    <message>
        <source>Could not save the recording: %1</source>
        <translation>記録を保存できませんでした: %1</translation>
    </message>
    <message>
        <source>Paused: the push moves the paper only while the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>一時停止中：押し込みはシミュレーションの実行中にだけ紙を動かします（Space で再生、Ctrl+. で1ステップ）。</translation>
    </message>
    <message>
        <source>The image size is width x height, each from 16 to %1 pixels, such as 1920x1080.</source>
        <translation>画像サイズは 幅 x 高さ で、それぞれ 16～%1 ピクセルです（例：1920x1080）。</translation>
    </message>
    <message>
        <source>Settled: the sheet stays as it is until the next edit.</source>
        <translation>静止しました：次の編集までシートはこのままです。</translation>
    </message>
    <message>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <source>Settling: the sheet comes to rest…</source>
        <translation>静止中：シートが落ち着くのを待っています…</translation>
    </message>
    <message>
        <source>Settling once the simulation plays (Space).</source>
        <translation>シミュレーションが動くと静止させます（スペース）。</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>ツール(&amp;T)</translation>
    </message>
    <message>
        <source>Paused: the grab moves the paper only while the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>一時停止中：つかむ操作はシミュレーションの実行中にだけ紙を動かします（Space で再生、Ctrl+. で1ステップ）。</translation>
    </message>
    <message>
        <source>Rendering the image (%1 x %2)…</source>
        <translation>画像をレンダリングしています (%1 x %2)…</translation>
    </message>
    <message>
        <source>Export Image</source>
        <translation>画像を書き出す</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 を書き出しました</translation>
    </message>
    <message>
        <source>An image is being exported; close once it is written.</source>
        <translation>画像を書き出しています。書き出しが終わってから閉じてください。</translation>
    </message>
    <message>
        <source>Paused: the fold is carried round once the simulation runs (Space plays, Ctrl+. steps).</source>
        <translation>一時停止中：シミュレーションが再生されると折りが行われます（Space で再生、Ctrl+. で1ステップ）。</translation>
    </message>
    <message>
        <source>Left drag pushes the paper · L folds, G grabs and I pins (Tools menu) · right drag orbits · the wheel zooms · F1 lists every key</source>
        <translation>左ドラッグで紙を押す・L で折る、G でつかむ、I でピン留め（ツールメニュー）・右ドラッグで回転・ホイールでズーム・F1 ですべてのキー</translation>
    </message>
    <message>
        <source>Folding: the paper is carried round the line, pressed and let go…</source>
        <translation>折っています：紙を線のまわりに運び、押さえ、放します…</translation>
    </message>
    <message>
        <source>Not folded: draw a longer line across the paper.</source>
        <translation>折れません：紙を横切るもっと長い線を引いてください。</translation>
    </message>
    <message>
        <source>Not folded: the line must cross the paper.</source>
        <translation>折れません：線が紙を横切っていません。</translation>
    </message>
    <message>
        <source>Not folded: there is paper on one side of the line only.</source>
        <translation>折れません：線の片側にしか紙がありません。</translation>
    </message>
    <message>
        <source>Not folded: the angle must lie between 1° and 180°.</source>
        <translation>折れません：角度は 1° から 180° の間にしてください。</translation>
    </message>
    <message>
        <source>Not folded: another edit is under way.</source>
        <translation>折れません：別の編集が進行中です。</translation>
    </message>
    <message>
        <source>Not folded: this way the flap would go through the desk, and pins hold the paper down. Fold the other way (Valley or Mountain), or unpin the paper.</source>
        <translation>折れません：この向きでは折り返しが机を突き抜け、ピンが紙を押さえているため持ち上げられません。反対向き（谷折りまたは山折り）に折るか、ピンを外してください。</translation>
    </message>
    <message>
        <source>Not folded: pins hold the paper on both sides of the line. Unpin one side: the pinned side stays, the other is folded over.</source>
        <translation>折れません：線の両側でピンが紙を押さえています。片側のピンを外してください。ピンのある側はそのまま残り、もう一方が折り返されます。</translation>
    </message>
    <message>
        <source>Not now: a fold is under way.</source>
        <translation>今はできません：折りの途中です。</translation>
    </message>
    <message>
        <source>Folded. Edit ▸ Undo unfolds the paper.</source>
        <translation>折りました。編集 ▸ 元に戻す で紙を開きます。</translation>
    </message>
    <message>
        <source>The fold opened %1° again after it was let go: its crease did not hold the flap. Edit ▸ Undo unfolds the paper.</source>
        <translation>離した後、折りが %1° 開きました：折り目がフラップを保てませんでした。編集 ▸ 元に戻す で紙を開きます。</translation>
    </message>
    <message>
        <source>Only part of the fold held: %1 % of the paper on the flap&apos;s side lies unfolded. The fold holds the paper that lies flat along the line, not layers above or below it. Edit ▸ Undo unfolds the paper.</source>
        <translation>折りは一部しか保たれませんでした：フラップ側の紙の %1 % が折られずに残っています。折りは線に沿って平らに置かれた紙を保ち、その上下の層は保ちません。編集 ▸ 元に戻す で紙を開きます。</translation>
    </message>
    <message>
        <source>Already settled: the sheet stays as it is until the next edit.</source>
        <translation>すでに静止しています：次の編集までシートはこのままです。</translation>
    </message>
    <message>
        <source>Not settled: an edit is under way. Settle once it is over.</source>
        <translation>静止できません：編集の途中です。終わってから静止させてください。</translation>
    </message>
    <message>
        <source>The fold is opening again: its crease does not hold the flap. Edit ▸ Undo unfolds the paper.</source>
        <translation>折りがまた開いています：折り目がフラップを保てません。編集 ▸ 元に戻す で紙を開きます。</translation>
    </message>
    <message>
        <source>The fold fell shut after it was let go: its crease cannot hold the flap up at %1°. Edit ▸ Undo unfolds the paper.</source>
        <translation>離した後、折りが閉じてしまいました：折り目は %1° でフラップを支えられません。編集 ▸ 元に戻す で紙を開きます。</translation>
    </message>
    <message>
        <source>The fold closed %1° further than asked after it was let go: its crease cannot hold the flap at that angle. Edit ▸ Undo unfolds the paper.</source>
        <translation>離した後、折りが指定より %1° 深く閉じました：折り目はその角度でフラップを保てません。編集 ▸ 元に戻す で紙を開きます。</translation>
    </message>
    <message>
        <source>Undo waits until the fold is let go.</source>
        <translation>元に戻すは、折りが手を離れるまで待ちます。</translation>
    </message>
    <message>
        <source>Undo waits until the sheet has settled.</source>
        <translation>元に戻すは、紙が落ち着くまで待ちます。</translation>
    </message>
    <message>
        <source>Undo waits until the mouse lets go of the paper.</source>
        <translation>元に戻すは、マウスが紙を放すまで待ちます。</translation>
    </message>
    <message>
        <source>Paused: the fold waits. Space plays and carries the paper round the line; Ctrl+. steps.</source>
        <translation>一時停止中：折りは待機しています。Space で再生すると紙が線の周りに折られます。Ctrl+. で1ステップ。</translation>
    </message>
    <message>
        <source>Undo waits until the fold is let go, and the simulation is paused: Space plays.</source>
        <translation>元に戻すは、折りが手を離れるまで待ちます。シミュレーションは一時停止中です：Space で再生。</translation>
    </message>
    <message>
        <source>The pins hold this paper taut: the hand pulls it with at most %1 N, as a pinch does before paper slips from it, and paper does not stretch to follow.</source>
        <translation>ピン留めがこの紙をぴんと張っています。手は最大 %1 N で引きます（それを超えると、つまんだ紙は指から滑ります）。紙は伸びてついて来ません。</translation>
    </message>
    <message>
        <source>This push moved nothing: the tool touched no paper, or slid over paper it cannot move (paper held by pins, say). Push where the paper is free, or unpin it.</source>
        <translation>この押し操作では何も動きませんでした。ツールが紙に触れなかったか、動かせない紙（ピンで留められた紙など）の上を滑りました。紙が自由な所を押すか、ピン留めを外してください。</translation>
    </message>
    <message>
        <source>Not now: the mouse holds the paper. Let go first.</source>
        <translation>今はできません：マウスが紙を押さえています。先に離してください。</translation>
    </message>
    <message>
        <source>&lt;new: %1&gt;</source>
        <translation>&lt;新しいシート: %1&gt;</translation>
    </message>
</context>
<context>
    <name>pf::PaperLookMenu</name>
    <message>
        <source>Could not use the picture as paper: %1</source>
        <translation>この画像は紙に使えません: %1</translation>
    </message>
    <message>
        <source>&amp;Paper</source>
        <translation>紙(&amp;P)</translation>
    </message>
    <message>
        <source>Paper &amp;Colour…</source>
        <translation>紙の色(&amp;C)…</translation>
    </message>
    <message>
        <source>&amp;Plain</source>
        <translation>無地(&amp;P)</translation>
    </message>
    <message>
        <source>Paper &amp;Grain</source>
        <translation>紙の地合い(&amp;G)</translation>
    </message>
    <message>
        <source>P&amp;icture: %1…</source>
        <translation>画像(&amp;I): %1…</translation>
    </message>
    <message>
        <source>P&amp;icture…</source>
        <translation>画像(&amp;I)…</translation>
    </message>
    <message>
        <source>Print a picture over the whole sheet</source>
        <translation>シート全体に画像を印刷します</translation>
    </message>
</context>
<context>
    <name>pf::ParameterPanel</name>
    <message>
        <source>φ fragility</source>
        <translation>φ 脆さ</translation>
    </message>
    <message>
        <source>Fragility φ scales the normal dot products of the break probability (Eq. 10). Larger φ: stiffer paper that breaks only where it is already curved; at 1 a flat region never breaks. Smaller φ: softer paper that crumples anywhere it is compressed.</source>
        <translation>脆さ φ は破断確率（式10）の法線の内積に掛かる係数です。φ が大きいと紙は硬く、すでに曲がっている所でしか破断しません（1 では平らな所は決して破断しません）。φ が小さいと紙は柔らかく、圧縮された所ならどこでもしわになります。</translation>
    </message>
    <message>
        <source>ψ recursive break</source>
        <translation>ψ 再帰的破断</translation>
    </message>
    <message>
        <source>ψ sets how far a new vertex moves out of the surface when a spring breaks (Eq. 11). At 1 the two halves keep the rest length and do not break again at once; smaller ψ leaves them compressed, so breaks repeat into finer crumples.</source>
        <translation>ψ はばねが破断したとき新しい頂点が面から出る距離を決めます（式11）。1 では2つの半分が自然長を保ち、すぐには再び破断しません。ψ が小さいと半分が圧縮されたまま残り、破断が繰り返されてより細かいしわになります。</translation>
    </message>
    <message>
        <source>σ shapes the subdivided surface that is drawn (§4.3): 0 keeps flat facets and sharp creases, larger values round them off. It does not change the simulation.</source>
        <translation>σ は描画される細分割面の形を決めます（§4.3）。0 では平らな面と鋭い折り目のまま、値を大きくすると丸みを帯びます。シミュレーションは変わりません。</translation>
    </message>
    <message>
        <source>Tool radius</source>
        <translation>ツールの半径</translation>
    </message>
    <message>
        <source>Radius of the sphere you push the paper with (Ctrl+wheel in the view).</source>
        <translation>紙を押す球の半径（ビュー内で Ctrl+ホイール）。</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>Advanced</source>
        <translation>詳細設定</translation>
    </message>
    <message>
        <source>Stretch stiffness</source>
        <translation>伸びの剛性</translation>
    </message>
    <message>
        <source>Bending stiffness</source>
        <translation>曲げ剛性</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>解像度</translation>
    </message>
    <message>
        <source>Vertices along the sheet&apos;s short side.</source>
        <translation>シートの短辺に沿った頂点数。</translation>
    </message>
    <message>
        <source>Sheet size</source>
        <translation>シートの大きさ</translation>
    </message>
    <message>
        <source>Resolution and size apply to the next New or Reset.</source>
        <translation>解像度と大きさは次の「新規」または「リセット」で反映されます。</translation>
    </message>
    <message>
        <source>Push depth</source>
        <translation>押し込みの深さ</translation>
    </message>
    <message>
        <source>How deep a push presses the sphere into the paper, as a share of its radius: deeper pushes crease harder.</source>
        <translation>押したときに球を紙へどれだけ深く押し込むか（半径に対する割合）。深いほど強く折り目がつきます。</translation>
    </message>
    <message>
        <source>Fold</source>
        <translation>折り</translation>
    </message>
    <message>
        <source>Valley</source>
        <translation>谷折り</translation>
    </message>
    <message>
        <source>Mountain</source>
        <translation>山折り</translation>
    </message>
    <message>
        <source>The Fold tool (L): draw a line across the paper; the lighter side (or the side without pins) is carried round it, pressed flat, opened to this angle and let go. A valley fold turns the flap up toward you, a mountain fold away from you, under the paper.</source>
        <translation>折るツール（L）：紙を横切る線を引きます。軽い側（またはピンのない側）が線のまわりに運ばれ、平らに押さえられ、この角度まで開かれてから放されます。谷折りは折り返しを手前（上）へ、山折りは奥（紙の下）へ折ります。</translation>
    </message>
    <message>
        <source>σ crumple smoothing</source>
        <translation>σ しわの滑らかさ</translation>
    </message>
</context>
<context>
    <name>pf::SolverPanel</name>
    <message>
        <source>tissue</source>
        <translation>ティッシュ</translation>
    </message>
    <message>
        <source>office</source>
        <translation>コピー用紙</translation>
    </message>
    <message>
        <source>card</source>
        <translation>厚紙</translation>
    </message>
    <message>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <source>max %1 %, RMS %2 %</source>
        <translation>最大 %1 %、RMS %2 %</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>積分器</translation>
    </message>
    <message>
        <source>Jacobi sweeps</source>
        <translation>ヤコビ反復回数</translation>
    </message>
    <message>
        <source>Steps per second</source>
        <translation>1秒あたりのステップ数</translation>
    </message>
    <message>
        <source>Cores used</source>
        <translation>使用コア数</translation>
    </message>
    <message numerus="yes">
        <source>How many of this computer&apos;s %n cores step the sheet. The sheet moves the same, to the last bit, on any number; by default one core is left to draw the view.</source>
        <translation>
            <numerusform>このコンピューターの %n 個のコアのうち、用紙の計算に使う数。どの数でも用紙の動きは最後のビットまで同じです。既定ではビューの描画用に 1 コアを残します。</numerusform>
        </translation>
    </message>
    <message>
        <source>Gravity outside the implicit filter</source>
        <translation>重力を陰的フィルターの外で積分</translation>
    </message>
    <message>
        <source>Start the Jacobi iteration at Δv = h·g. The paper&apos;s step divides gravity by W, so a hanging sheet falls at a fraction of g; this keeps free fall exact at the same stability.</source>
        <translation>ヤコビ反復を Δv = h·g から始めます。論文のステップは重力を W で割るため、吊るしたシートは g のごく一部の加速度でしか落ちません。これにより同じ安定性のまま自由落下が正確になります。</translation>
    </message>
    <message>
        <source>Step time</source>
        <translation>ステップ時間</translation>
    </message>
    <message>
        <source>Stretch</source>
        <translation>伸び</translation>
    </message>
    <message>
        <source>max(l/l0 - 1, 0) over the uncreased structural springs, live: how far the paper is pulled longer (edges that paper bending between two vertices shortens do not count)</source>
        <translation>折り目のない構造ばねの max(l/l0 - 1, 0)（ライブ）：紙がどれだけ引き伸ばされているか（二つの頂点の間で紙が曲がって縮んだ辺は数えません）</translation>
    </message>
    <message>
        <source>Open Latest Chart…</source>
        <translation>最新のグラフを開く…</translation>
    </message>
    <message>
        <source>Show the newest speed–accuracy chart written by &apos;paperfold bench&apos;.</source>
        <translation>「paperfold bench」が書き出した最新の速度と精度のグラフを表示します。</translation>
    </message>
    <message>
        <source>jacobi: the paper&apos;s approximate implicit step (Eq. 6); jacobi-scalar: the same with k·I blocks; symplectic: explicit; backward-euler: the exact implicit step (slow, the reference); xpbd: paper from its physical constants (docs/material.md).</source>
        <translation>jacobi: 論文の近似陰的ステップ (式 6)。jacobi-scalar: k·I ブロックを用いた同じもの。symplectic: 陽的。backward-euler: 厳密な陰的ステップ (低速、基準)。xpbd: 物理定数に基づく紙 (docs/material.md)。</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>紙</translation>
    </message>
    <message>
        <source>The paper&apos;s weight, stretch and bending stiffness and friction, used by the xpbd integrator: tissue 20 g/m², office 80 g/m², card 250 g/m².</source>
        <translation>xpbd 積分器が使う紙の重さ、伸び剛性、曲げ剛性、摩擦: ティッシュ 20 g/m²、コピー用紙 80 g/m²、厚紙 250 g/m²。</translation>
    </message>
    <message numerus="yes">
        <source>%n per second</source>
        <translation>
            <numerusform>毎秒 %n</numerusform>
        </translation>
    </message>
    <message>
        <source>Breaks</source>
        <translation>破断</translation>
    </message>
    <message>
        <source>Breaks in the last second of simulated time: paper breaks while it is loaded further, and stops when the load stops</source>
        <translation>シミュレーション時間の直近 1 秒間の破断数: 紙は荷重が増え続ける間に破断し、荷重が止まると破断も止まります</translation>
    </message>
    <message>
        <source>How many steps one simulated second takes (the step h = 1/N s). More steps are more accurate and cost more: the sheet moves in real time while the computer can take them that fast. The paper&apos;s behaviour is checked at 240 (&apos;paperfold fidelity&apos;).</source>
        <translation>シミュレーション1秒あたりのステップ数（ステップ幅 h = 1/N 秒）。ステップを増やすと精度は上がり、計算量も増えます。コンピュータがその速さで計算できる間は、紙は実時間で動きます。紙のふるまいは 240 で検証されています（&apos;paperfold fidelity&apos;）。</translation>
    </message>
</context>
<context>
    <name>pf::StatusReadout</name>
    <message>
        <source>%1 · paused</source>
        <translation>%1 · 一時停止中</translation>
    </message>
    <message>
        <source>In brackets: the breaks in the last second of simulated time, which lasts longer than a second on the clock while the sheet runs behind real time</source>
        <translation>括弧内: シミュレーション時間の直近 1 秒間の破断数。シートが実時間より遅く動いている間、この 1 秒は時計では 1 秒より長くかかります</translation>
    </message>
    <message>
        <source>%1 · %2× real time</source>
        <translation>%1 · 実時間の%2倍</translation>
    </message>
    <message>
        <source>The computer cannot take the steps as fast as they happen: the sheet moves slower than in real time. Fewer steps per second (Solver dock), a smaller sheet or another integrator are faster.</source>
        <translation>コンピュータが時間どおりにステップを計算できません。紙は実時間より遅く動いています。1秒あたりのステップ数を減らす（ソルバー）、紙を小さくする、別の積分器を選ぶと速くなります。</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 fps</translation>
    </message>
    <message>
        <source>step %1 µs</source>
        <translation>ステップ %1 µs</translation>
    </message>
    <message>
        <source>%1 · at rest</source>
        <translation>%1 · 静止</translation>
    </message>
    <message>
        <source>%1 vertices · %2 springs · %3 (%4/s) · %5</source>
        <translation>頂点 %1 · ばね %2 · %3 (%4/秒) · %5</translation>
    </message>
    <message numerus="yes">
        <source>%n break(s)</source>
        <translation>
            <numerusform>破断 %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n hinge(s)</source>
        <translation>
            <numerusform>ヒンジ %n</numerusform>
        </translation>
    </message>
    <message>
        <source>no step yet</source>
        <translation>まだステップなし</translation>
    </message>
    <message>
        <source>at rest</source>
        <translation>静止</translation>
    </message>
    <message>
        <source>settled</source>
        <translation>固定</translation>
    </message>
    <message>
        <source>%1 · settled</source>
        <translation>%1 · 固定</translation>
    </message>
    <message>
        <source>– fps</source>
        <translation>– fps</translation>
    </message>
    <message>
        <source>Nothing moves, so the view is not drawn again until something changes.</source>
        <translation>何も動いていないため、何かが変わるまで表示は再描画されません。</translation>
    </message>
</context>
<context>
    <name>pf::StrokeHistory</name>
    <message>
        <source>Could not undo “%1”: the paper is no longer as this step left it.</source>
        <translation>「%1」を元に戻せませんでした：紙はもうこの操作が終わったときの状態ではありません。</translation>
    </message>
    <message>
        <source>Could not redo “%1”: the paper is no longer as this step found it.</source>
        <translation>「%1」をやり直せませんでした：紙はもうこの操作が始まったときの状態ではありません。</translation>
    </message>
</context>
<context>
    <name>pf::Viewport</name>
    <message>
        <source>OpenGL 3.3 is not available (missing %1)</source>
        <translation>OpenGL 3.3 が利用できません（%1 がありません）</translation>
    </message>
</context>
</TS>
